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
} // namespace feticon::mesh
