#pragma once
/// Small hand-built meshes for the fem unit tests (independent of the mesh generators).

#include "mesh/mesh.hpp"

#include <cmath>

namespace feticon::test
{
/// A 2x2x2 patch of the unit cube whose 27 nodes are perturbed (all but the 8 corners),
/// so that every element is a distorted hexahedron. Node set "boundary" holds the 26
/// boundary nodes, "interior" the centre node.
inline mesh::Mesh distorted_patch()
{
  mesh::Mesh m;
  m.nodes.resize(27, 3);
  auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
      {
        Eigen::Vector3d x(0.5 * i, 0.5 * j, 0.5 * k);
        // Perturb along the directions in which the node may move without leaving its
        // boundary face/edge (a coordinate at 0 or 1 stays put).
        const double s = 0.08 * std::sin(1.7 * i + 2.3 * j + 0.9 * k + 0.4);
        for (int d = 0; d < 3; ++d)
          if (x(d) > 0 && x(d) < 1)
            x(d) += s * (d + 1) / 3.0;
        m.nodes.row(id(i, j, k)) = x.transpose();
      }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.cells.add(feticon::mesh::CellKind::hex8,
                    feticon::mesh::Hex8Nodes{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                             id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                             id(i, j + 1, k + 1)});
  m.cell_body.assign(8, 0);
  m.body_names = {"patch"};
  for (int n = 0; n < 27; ++n)
    (n == id(1, 1, 1) ? m.node_sets["interior"] : m.node_sets["boundary"]).push_back(n);
  return m;
}

/// The unit cube as one hex8 cell; face set "xmax" (x = 1), node sets for each face.
inline mesh::Mesh unit_cube()
{
  mesh::Mesh m;
  m.nodes.resize(8, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  m.cells.add(feticon::mesh::CellKind::hex8, feticon::mesh::Hex8Nodes{0, 1, 2, 3, 4, 5, 6, 7});
  m.cell_body = {0};
  m.body_names = {"cube"};
  m.face_sets["xmax"] = {{1, 2, 6, 5}};
  m.node_sets["xmax"] = {1, 2, 5, 6};
  m.node_sets["ymax"] = {2, 3, 6, 7};
  m.node_sets["zmax"] = {4, 5, 6, 7};
  return m;
}
} // namespace feticon::test
