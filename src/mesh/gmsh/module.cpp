/// @file The entry of libfeticon_gmsh.so: the function table of mesh/gmsh_module.hpp, with
/// every exception turned into its message (exceptions do not cross the module boundary).

#include "mesh/gmsh/gmsh_operations.hpp"

#include <exception>

namespace feticon::mesh
{
namespace
{
template <class Operation>
std::string error_of(Operation&& operation)
{
  try
  {
    operation();
    return {};
  }
  catch (const std::exception& exception)
  {
    return exception.what();
  }
  catch (...)
  {
    return "Gmsh module: unknown error";
  }
}

std::string mesh_cross_section(const CrossSection& section, const SizeField& size, QuadSection& out)
{
  return error_of([&] { out = mesh_cross_section_with_gmsh(section, size); });
}

std::string read_model(const std::filesystem::path& path, const std::string& where, Mesh& out)
{
  return error_of([&] { out = read_model_with_gmsh(path, where); });
}

std::string mesh_sphere_on_half_space(const SphereOnHalfSpace& geometry, Mesh& out)
{
  return error_of([&] { out = mesh_sphere_on_half_space_with_gmsh(geometry); });
}

const GmshModule module{gmsh_module_abi, &mesh_cross_section, &read_model, &mesh_sphere_on_half_space};
} // namespace
} // namespace feticon::mesh

extern "C" __attribute__((visibility("default"))) const feticon::mesh::GmshModule* feticon_gmsh_module()
{
  return &feticon::mesh::module;
}
