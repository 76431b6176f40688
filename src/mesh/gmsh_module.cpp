#include "mesh/gmsh_module.hpp"

#include "common/error.hpp"

#include <dlfcn.h>

#include <string>
#include <system_error>
#include <vector>

namespace feticon::mesh
{
namespace
{
/// Where the module may be, in the order tried.
std::vector<std::filesystem::path> module_candidates()
{
  std::vector<std::filesystem::path> candidates;
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error)
    candidates.push_back(executable.parent_path() / "libfeticon_gmsh.so");
  candidates.emplace_back(FETICON_GMSH_MODULE_PATH);         // the build tree's (tests, bench)
  candidates.emplace_back(FETICON_GMSH_MODULE_INSTALL_PATH); // the installed one (cmake --install)
  return candidates;
}

const GmshModule* load_gmsh_module()
{
  std::error_code error;
  std::string tried;
  for (const std::filesystem::path& path : module_candidates())
  {
    if (!std::filesystem::exists(path, error))
    {
      tried += " " + path.string() + " (no such file);";
      continue;
    }
    // RTLD_LOCAL: libgmsh stays out of the global scope of later loads. RTLD_LAZY: the
    // libraries of libgmsh not linked with BIND_NOW bind their functions on first call, as
    // they would when linked (RTLD_NOW doubles the load time: docs/measurements.md).
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle)
    {
      tried += " " + path.string() + " (" + dlerror() + ");";
      continue;
    }
    using Entry = const GmshModule* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, "feticon_gmsh_module"));
    const GmshModule* module = entry ? entry() : nullptr;
    if (module && module->abi_version == gmsh_module_abi)
      return module; // kept loaded until the process ends
    tried += " " + path.string() +
        (module ? " (built from other sources: rebuild feticon);" : " (not feticon's Gmsh module);");
    dlclose(handle);
  }
  FETICON_CHECK(false,
                "cannot load feticon's Gmsh module, needed to mesh with Gmsh or read a "
                ".msh file; tried"
                    << tried);
  return nullptr;
}
} // namespace

std::string gmsh_module_stamp()
{
  std::error_code error;
  for (const std::filesystem::path& path : module_candidates())
    if (std::filesystem::exists(path, error))
    {
      const auto size = std::filesystem::file_size(path, error);
      const auto time = std::filesystem::last_write_time(path, error);
      if (error)
        return {};
      return std::to_string(size) + ":" + std::to_string(time.time_since_epoch().count());
    }
  return {};
}

const GmshModule& gmsh_module()
{
  static const GmshModule* const module = load_gmsh_module();
  return *module;
}
} // namespace feticon::mesh
