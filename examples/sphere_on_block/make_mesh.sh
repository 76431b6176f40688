#!/usr/bin/env bash
# Regenerates sphere_on_block.msh from sphere_on_block.geo with the gmsh binary (Debian package
# gmsh, see scripts/install-deps.sh). Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -3 -format msh41 sphere_on_block.geo -o sphere_on_block.msh
