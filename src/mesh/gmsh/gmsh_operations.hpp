#pragma once
/// @file What libfeticon_gmsh.so does with Gmsh (see mesh/gmsh_module.hpp): inside the module
/// only. Errors are thrown as feticon::Error; module.cpp turns them into messages.

#include "mesh/gmsh_module.hpp"

namespace feticon::mesh
{
/// Gmsh's quadrilateral mesh of the section's surface with the element size `size`.
QuadSection mesh_cross_section_with_gmsh(const CrossSection& section, const SizeField& size);

/// The hexahedra, bodies and sets of a .msh file (read_gmsh has checked the file first).
Mesh read_model_with_gmsh(const std::filesystem::path& path, const std::string& where);
/// The cells, bodies and sets of the model open in the current Gmsh session.
Mesh read_open_model(const std::string& where);
/// The hertz3d quarter model meshed with tetrahedra (mesh/gmsh_module.hpp).
Mesh mesh_sphere_on_half_space_with_gmsh(const SphereOnHalfSpace& geometry);
} // namespace feticon::mesh
