#!/usr/bin/env python3
"""The discrete catenary: where a chain of equal point masses on rigid links
hangs at rest between two posts at the same height (double precision).

    catenary.py [--links 8] [--length 0.1] [--span 0.6] [--cpp]

Posts at (0, 0) and (span, 0); links-1 beads of equal mass. At rest the
horizontal pull H is the same in every link, and the vertical pull drops by
one bead's weight w at each bead; by symmetry each post carries half the
beads, so link j (j = 0 .. links-1, from the left post) has slope
    tan(phi_j) = (links/2 - j - 1/2) * w / H.
Only w / H is unknown: it is found by bisection so that the links span the
posts, sum(length * cos(phi_j)) = span; the beads follow link by link.
The masses drop out: any equal masses hang the same way.

Prints the beads' coordinates, or with --cpp the constants extras/test/RopeTest
uses (that test's numbers were made by `catenary.py --cpp`).
"""
import argparse
import math


def slopes(links, ratio):
    return [(links / 2.0 - j - 0.5) * ratio for j in range(links)]


def span_of(links, length, ratio):
    return sum(length / math.sqrt(1 + t * t) for t in slopes(links, ratio))


def solve(links, length, span):
    if not 0 < span < links * length:
        raise SystemExit("the posts must be closer than the chain is long")
    lo, hi = 0.0, 1.0
    while span_of(links, length, hi) > span:  # steeper links span less
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        if span_of(links, length, mid) > span:
            lo = mid
        else:
            hi = mid
    ratio = (lo + hi) / 2
    beads, x, y = [], 0.0, 0.0
    for t in slopes(links, ratio)[:-1]:
        c = 1 / math.sqrt(1 + t * t)
        x += length * c
        y -= length * t * c
        beads.append((x, y))
    return ratio, beads


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--links", type=int, default=8)
    ap.add_argument("--length", type=float, default=0.1)
    ap.add_argument("--span", type=float, default=0.6)
    ap.add_argument("--cpp", action="store_true")
    a = ap.parse_args()
    ratio, beads = solve(a.links, a.length, a.span)
    sag = -min(y for _, y in beads)
    if a.cpp:
        print("// Made by extras/benchmarks/tools/catenary.py --links %d "
              "--length %g --span %g --cpp" % (a.links, a.length, a.span))
        print("const float kCatenarySag = %.9f;  // m, depth of the lowest bead" % sag)
        print("const float kCatenary[%d][2] = {" % len(beads))
        for x, y in beads:
            print("    {%.9ff, %.9ff}," % (x, y))
        print("};")
        return
    print("w/H = %.12g, sag = %.12g m" % (ratio, sag))
    for k, (x, y) in enumerate(beads, 1):
        print("bead %d: %.12f %.12f" % (k, x, y))


if __name__ == "__main__":
    main()
