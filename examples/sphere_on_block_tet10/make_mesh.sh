#!/usr/bin/env bash
# Regenerates sphere_on_block_tet10.msh from sphere_on_block_tet10.geo with the gmsh binary (Debian package
# gmsh, see scripts/install-deps.sh). Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -3 -format msh41 sphere_on_block_tet10.geo -o sphere_on_block_tet10.msh
