#!/usr/bin/env bash
# Regenerates rubber_seal.msh from rubber_seal.geo with the gmsh binary (Debian package gmsh, see
# scripts/install-deps.sh). Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -2 -format msh41 rubber_seal.geo -o rubber_seal.msh
