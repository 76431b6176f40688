#!/usr/bin/python3
"""A tower of eight bodies (issue 63's compact assembly, beside the pack of leaves): four
levels of examples/sphere_on_block, each a steel block with a punch whose spherical lower face
(R = 50 mm) rests on it, and the next level's block resting on the punch's flat top. Seven
frictionless mortar pairs: four curved (punch on block, Hertz-like, contact growing from a point)
and three flat (the punch's 10 x 10 mm top on the block above, a flat punch with its edge
singularity). Quarter model (symmetry planes x = 0 and y = 0), all-hex Gmsh meshes that do not
match across any pair; the lowest block on a rigid foundation, 50 MPa on the top punch, every body
above the lowest held by contact alone.

    bench/sphere_stack.py DIR [--scale S] [--displacements small|large]
    gmsh -3 -format msh41 DIR/sphere_stack.geo -o DIR/sphere_stack.msh
    build/feticon run DIR/problem.yaml

Writes DIR/sphere_stack.geo and DIR/problem.yaml. SCALE 1: the example's cells on every level
(67 848 DOFs); the DOFs grow as SCALE^3 (SCALE 2: 486 360). `--levels 1` is the one-pair
sphere on a block of the same meshes (SCALE 2.07: 135 696 DOFs), the yardstick of time per DOF.
"""
import argparse
import os

LEVEL_TEMPLATE = """
// ---- level {k}: punch (spherical lower face at z = {z0}) and the block under it ----------
Point({o}1) = {{0, 0, {z0}}};
Point({o}2) = {{a, 0, {z0} + R - Sqrt(R^2 - a^2)}};
Point({o}3) = {{a, a, {z0} + R - Sqrt(R^2 - 2 * a^2)}};
Point({o}4) = {{0, a, {z0} + R - Sqrt(R^2 - a^2)}};
Point({o}5) = {{0, 0, {z0} + H}};
Point({o}6) = {{a, 0, {z0} + H}};
Point({o}7) = {{a, a, {z0} + H}};
Point({o}8) = {{0, a, {z0} + H}};
Point({o}9) = {{0, 0, {z0} + R}};
Point({o}10) = {{a, 0, {z0} + R}};
Point({o}11) = {{0, a, {z0} + R}};
Circle({o}1) = {{{o}1, {o}9, {o}2}};
Circle({o}2) = {{{o}4, {o}11, {o}3}};
Line({o}3) = {{{o}5, {o}6}};
Line({o}4) = {{{o}8, {o}7}};
Circle({o}5) = {{{o}1, {o}9, {o}4}};
Circle({o}6) = {{{o}2, {o}10, {o}3}};
Line({o}7) = {{{o}5, {o}8}};
Line({o}8) = {{{o}6, {o}7}};
Line({o}9) = {{{o}1, {o}5}};
Line({o}10) = {{{o}2, {o}6}};
Line({o}11) = {{{o}3, {o}7}};
Line({o}12) = {{{o}4, {o}8}};
Curve Loop({o}1) = {{{o}1, {o}6, -{o}2, -{o}5}};
Surface({o}1) = {{{o}1}} In Sphere {{{o}9}};
Curve Loop({o}2) = {{{o}3, {o}8, -{o}4, -{o}7}};
Plane Surface({o}2) = {{{o}2}};
Curve Loop({o}3) = {{{o}1, {o}10, -{o}3, -{o}9}};
Plane Surface({o}3) = {{{o}3}};
Curve Loop({o}4) = {{{o}6, {o}11, -{o}8, -{o}10}};
Plane Surface({o}4) = {{{o}4}};
Curve Loop({o}5) = {{{o}2, {o}11, -{o}4, -{o}12}};
Plane Surface({o}5) = {{{o}5}};
Curve Loop({o}6) = {{{o}5, {o}12, -{o}7, -{o}9}};
Plane Surface({o}6) = {{{o}6}};
Surface Loop({o}1) = {{{o}1, {o}2, {o}3, {o}4, {o}5, {o}6}};
Volume({o}1) = {{{o}1}};
Transfinite Curve{{{o}1, {o}2, {o}3, {o}4, {o}5, {o}6, {o}7, {o}8}} = n_punch + 1 Using Progression r_punch;
Transfinite Curve{{{o}9, {o}10, {o}11, {o}12}} = n_punch_z + 1 Using Progression r_z;
Transfinite Surface{{{o}1, {o}2, {o}3, {o}4, {o}5, {o}6}};
Recombine Surface{{{o}1, {o}2, {o}3, {o}4, {o}5, {o}6}};
Transfinite Volume{{{o}1}} = {{{o}1, {o}2, {o}3, {o}4, {o}5, {o}6, {o}7, {o}8}};

Point({o}21) = {{0, 0, {z0}}};
Point({o}22) = {{b, 0, {z0}}};
Point({o}23) = {{b, b, {z0}}};
Point({o}24) = {{0, b, {z0}}};
Point({o}25) = {{0, 0, {z0} - d}};
Point({o}26) = {{b, 0, {z0} - d}};
Point({o}27) = {{b, b, {z0} - d}};
Point({o}28) = {{0, b, {z0} - d}};
Line({o}21) = {{{o}21, {o}22}};
Line({o}22) = {{{o}24, {o}23}};
Line({o}23) = {{{o}25, {o}26}};
Line({o}24) = {{{o}28, {o}27}};
Line({o}25) = {{{o}21, {o}24}};
Line({o}26) = {{{o}22, {o}23}};
Line({o}27) = {{{o}25, {o}28}};
Line({o}28) = {{{o}26, {o}27}};
Line({o}29) = {{{o}21, {o}25}};
Line({o}30) = {{{o}22, {o}26}};
Line({o}31) = {{{o}23, {o}27}};
Line({o}32) = {{{o}24, {o}28}};
Curve Loop({o}21) = {{{o}21, {o}26, -{o}22, -{o}25}};
Plane Surface({o}21) = {{{o}21}};
Curve Loop({o}22) = {{{o}23, {o}28, -{o}24, -{o}27}};
Plane Surface({o}22) = {{{o}22}};
Curve Loop({o}23) = {{{o}21, {o}30, -{o}23, -{o}29}};
Plane Surface({o}23) = {{{o}23}};
Curve Loop({o}24) = {{{o}26, {o}31, -{o}28, -{o}30}};
Plane Surface({o}24) = {{{o}24}};
Curve Loop({o}25) = {{{o}22, {o}31, -{o}24, -{o}32}};
Plane Surface({o}25) = {{{o}25}};
Curve Loop({o}26) = {{{o}25, {o}32, -{o}27, -{o}29}};
Plane Surface({o}26) = {{{o}26}};
Surface Loop({o}21) = {{{o}21, {o}22, {o}23, {o}24, {o}25, {o}26}};
Volume({o}21) = {{{o}21}};
Transfinite Curve{{{o}21, {o}22, {o}23, {o}24, {o}25, {o}26, {o}27, {o}28}} = n_base + 1 Using Progression r_base;
Transfinite Curve{{{o}29, {o}30, {o}31, {o}32}} = n_base_z + 1 Using Progression r_z;
Transfinite Surface{{{o}21, {o}22, {o}23, {o}24, {o}25, {o}26}};
Recombine Surface{{{o}21, {o}22, {o}23, {o}24, {o}25, {o}26}};
Transfinite Volume{{{o}21}} = {{{o}21, {o}22, {o}23, {o}24, {o}25, {o}26, {o}27, {o}28}};
Physical Volume("punch{k}") = {{{o}1}};
Physical Volume("block{k}") = {{{o}21}};
Physical Surface("punch{k}_bottom") = {{{o}1}};
Physical Surface("punch{k}_top") = {{{o}2}};
Physical Surface("block{k}_top") = {{{o}21}};
Physical Surface("block{k}_bottom") = {{{o}22}};
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dir")
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--levels", type=int, default=4)
    parser.add_argument("--displacements", choices=["small", "large"], default="large")
    args = parser.parse_args()
    s = args.scale
    # The example's cells times SCALE, its geometric grading kept (progression^(1/SCALE)).
    cells = {"n_punch": 14, "n_punch_z": 10, "n_base": 16, "n_base_z": 10}
    ratios = {"r_punch": 1.12, "r_base": 1.167, "r_z": 1.2}
    H, d = 0.012, 0.01
    lines = ['SetFactory("Built-in");', "R = 0.05; a = 0.01; H = %g; b = 0.02; d = %g;" % (H, d)]
    lines += ["%s = %d;" % (k, max(1, round(v * s))) for k, v in cells.items()]
    lines += ["%s = %.6f;" % (k, v ** (1.0 / s)) for k, v in ratios.items()]
    for k in range(args.levels):
        lines.append(LEVEL_TEMPLATE.format(k=k, o=k + 1, z0="%.6g" % (k * (H + d))))
    x0 = ", ".join("%d6, %d26" % (k + 1, k + 1) for k in range(args.levels))
    y0 = ", ".join("%d3, %d23" % (k + 1, k + 1) for k in range(args.levels))
    lines += ['Physical Surface("symmetry_x") = {%s};' % x0, 'Physical Surface("symmetry_y") = {%s};' % y0]
    lines += ["Mesh.MshFileVersion = 4.1;", "Mesh.SaveAll = 0;"]
    os.makedirs(args.dir, exist_ok=True)
    with open(os.path.join(args.dir, "sphere_stack.geo"), "w") as geo:
        geo.write("\n".join(lines) + "\n")
    top = args.levels - 1
    problem = ["problem: custom", "mesh:", "  file: sphere_stack.msh", "bodies:"]
    for k in range(args.levels):
        problem += ["  block%d: {young: 2.1e11, poisson: 0.3}" % k, "  punch%d: {young: 2.1e11, poisson: 0.3}" % k]
    problem += ["supports:", "  - {set: block0_bottom, x: 0, y: 0, z: 0}", "  - {set: symmetry_x, x: 0}",
                "  - {set: symmetry_y, y: 0}", "loads:", "  - {set: punch%d_top, traction: [0, 0, -5e7]}" % top,
                "contact:"]
    for k in range(args.levels):
        problem.append("  - {slave: punch%d_bottom, master: block%d_top}" % (k, k))
        if k + 1 < args.levels:
            problem.append("  - {slave: punch%d_top, master: block%d_bottom}" % (k, k + 1))
    problem.append("displacements: %s" % args.displacements)
    with open(os.path.join(args.dir, "problem.yaml"), "w") as out:
        out.write("\n".join(problem) + "\n")


if __name__ == "__main__":
    main()
