"""Writes an ASCII STL of a closed box tank [0, X] x [0, Y] x [0, Z] (y up) with a box obstacle,
every facet's normal into the fluid (data/scenes/hydrostatic_block_emps_3d.yaml).

    scripts/tank_with_box_stl X Y Z BOX_X0 BOX_X1 BOX_Y0 BOX_Y1 BOX_Z0 BOX_Z1 > FILE.stl

With BOX_Y0 = 0 the box stands on the floor and both are one watertight surface (the floor has
the box's footprint cut out, the box has no bottom); with BOX_Y0 > 0 it is a closed box of its
own held above the floor."""
import sys


def main(argv):
    if len(argv) != 10:
        print("usage: scripts/tank_with_box_stl X Y Z BOX_X0 BOX_X1 BOX_Y0 BOX_Y1 BOX_Z0 BOX_Z1",
              file=sys.stderr)
        sys.exit(2)
    X, Y, Z, x0, x1, bottom, top, z0, z1 = (float(a) for a in argv[1:])
    if not (0 < x0 < x1 < X and 0 < z0 < z1 < Z and 0 <= bottom < top < Y):
        print("tank_with_box_stl: the box must lie inside the tank, below its lid", file=sys.stderr)
        sys.exit(2)
    xs, zs = [0.0, x0, x1, X], [0.0, z0, z1, Z]
    facets = []  # (a, b, c, n): n the normal into the fluid

    def quad(a, b, c, d, n):  # a planar quadrilateral a b c d, two triangles
        facets.append((a, b, c, n))
        facets.append((a, c, d, n))

    def fan(apex, chain, n):  # a convex polygon as triangles from apex over the chain
        for p, q in zip(chain, chain[1:]):
            facets.append((apex, p, q, n))

    if bottom > 0:  # a floating box: the tank's faces whole, the box closed
        xs, zs = [0.0, X], [0.0, Z]
        quad((x0, bottom, z0), (x1, bottom, z0), (x1, bottom, z1), (x0, bottom, z1), (0, -1, 0))
    for i in range(len(xs) - 1):  # the floor (without the footprint of a box standing on it)
        for k in range(len(zs) - 1):
            if bottom == 0 and i == 1 and k == 1:
                continue
            quad((xs[i], 0, zs[k]), (xs[i + 1], 0, zs[k]), (xs[i + 1], 0, zs[k + 1]),
                 (xs[i], 0, zs[k + 1]), (0, 1, 0))
    quad((0, Y, 0), (X, Y, 0), (X, Y, Z), (0, Y, Z), (0, -1, 0))  # the lid
    # The side walls: their bottom edges through the footprint's lines, fanned from a top corner.
    fan((0, Y, 0), [(0, 0, z) for z in zs] + [(0, Y, Z)], (1, 0, 0))
    fan((X, Y, 0), [(X, 0, z) for z in zs] + [(X, Y, Z)], (-1, 0, 0))
    fan((0, Y, 0), [(x, 0, 0) for x in xs] + [(X, Y, 0)], (0, 0, 1))
    fan((0, Y, Z), [(x, 0, Z) for x in xs] + [(X, Y, Z)], (0, 0, -1))
    # The box: its top and four sides, normals out of it.
    quad((x0, top, z0), (x1, top, z0), (x1, top, z1), (x0, top, z1), (0, 1, 0))
    quad((x0, bottom, z0), (x0, bottom, z1), (x0, top, z1), (x0, top, z0), (-1, 0, 0))
    quad((x1, bottom, z0), (x1, bottom, z1), (x1, top, z1), (x1, top, z0), (1, 0, 0))
    quad((x0, bottom, z0), (x1, bottom, z0), (x1, top, z0), (x0, top, z0), (0, 0, -1))
    quad((x0, bottom, z1), (x1, bottom, z1), (x1, top, z1), (x0, top, z1), (0, 0, 1))

    out = ["solid tank_with_box"]
    for a, b, c, n in facets:
        ab = [b[j] - a[j] for j in range(3)]
        ac = [c[j] - a[j] for j in range(3)]
        cross = (ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                 ab[0] * ac[1] - ab[1] * ac[0])
        if sum(cross[j] * n[j] for j in range(3)) < 0:  # corners counter-clockwise seen from n
            b, c = c, b
        out.append("  facet normal %g %g %g" % n)
        out.append("    outer loop")
        out.extend("      vertex %.9g %.9g %.9g" % p for p in (a, b, c))
        out.append("    endloop")
        out.append("  endfacet")
    out.append("endsolid tank_with_box")
    print("\n".join(out))


if __name__ == "__main__":
    main(sys.argv)
