#!/usr/bin/python3
"""An independent reading of a DXF file with ezdxf (Debian's python3-ezdxf), for the DXF tests.

Prints JSON: the model-space entity counts by type (what ezdxf's modelspace() lists), the total
length of every contour entity with INSERTs expanded (ezdxf's own block transforms and paths,
flattened to 0.2 um), and the chaining of those entities as a graph of their ends (ends within
the tolerance are one node): components, how many are simple loops (every node met by two ends),
the areas of those loops (shapely, from the flattened paths), and the nodes met by an odd number
of ends (open ends). Kerf's reader, chaining and area are checked against these numbers.
"""
import json
import math
import sys

import ezdxf
from shapely.geometry import Polygon

SAGITTA = 1e-6  # mm: how far the flattened points may leave a curve
CURVE_TOLERANCE = 0.001  # mm: Kerf's biarcs for splines and ellipses (--curve-tolerance's default)
CONTOUR = {"LINE", "ARC", "CIRCLE", "LWPOLYLINE", "POLYLINE", "SPLINE", "ELLIPSE"}


def main():
    file = sys.argv[1]
    tol = float(sys.argv[2]) if len(sys.argv) > 2 else 0.001
    doc = ezdxf.readfile(file)
    msp = doc.modelspace()
    counts = {}
    for e in msp:
        counts[e.dxftype()] = counts.get(e.dxftype(), 0) + 1
    pieces = []  # each a list of points along one primitive, in its own direction
    slack = []  # per piece: (length, area) the flattening may have lost
    fitted = []  # per piece: its length when Kerf fits it with biarcs (splines, ellipses)

    def fitted_area(members):
        return sum(CURVE_TOLERANCE * fitted[m] for m in members)
    for e in expand_inserts(msp):
        kind = e.dxftype()
        if kind not in CONTOUR:
            continue
        if kind == "POLYLINE" and (e.is_polygon_mesh or e.is_poly_face_mesh):
            continue
        if kind in ("LWPOLYLINE", "POLYLINE"):
            e.dxf.layer = "0"  # ezdxf 0.18 refuses to copy a layer name like "PLASMA:1 Slo:!" to the parts
            parts = list(e.virtual_entities())
        else:
            parts = [e]
        for part in parts:
            pts = points_of(part)
            if len(pts) >= 2 and sum(math.dist(pts[i], pts[i + 1]) for i in range(len(pts) - 1)) > 1e-9:
                pieces.append(pts)
                # Kerf fits splines and ellipses with biarcs within its curve tolerance (0.001 mm).
                fitted.append(sum(math.dist(pts[i], pts[i + 1]) for i in range(len(pts) - 1))
                              if part.dxftype() in ("SPLINE", "ELLIPSE") else 0.0)
                curved = part.dxftype() != "LINE"
                chords = [math.dist(pts[i], pts[i + 1]) for i in range(len(pts) - 1)]
                # A chord c whose curve leaves it by at most s: the curve is longer by at most
                # 8 s^2 / (3 c) and encloses at most (2/3) c s more.
                slack.append((sum(8 * SAGITTA**2 / (3 * c) for c in chords if c > 0) if curved else 0.0,
                              sum(2 * c * SAGITTA / 3 for c in chords) if curved else 0.0))
    length = 0.0
    for pts in pieces:
        length += sum(math.dist(pts[i], pts[i + 1]) for i in range(len(pts) - 1))
    # Ends into nodes (naive clustering within the tolerance).
    nodes = []

    spread = []  # per node: how far its ends lie from it (a chainer snaps them together)

    def node_of(p):
        for i, q in enumerate(nodes):
            if math.dist(p, q) <= tol:
                spread[i] = max(spread[i], math.dist(p, q))
                return i
        nodes.append(p)
        spread.append(0.0)
        return len(nodes) - 1

    edges = []
    for pts in pieces:
        if math.dist(pts[0], pts[-1]) <= 1e-9 and len(pts) > 2:
            edges.append((None, None, pts))  # closed on its own
        else:
            edges.append((node_of(pts[0]), node_of(pts[-1]), pts))
    degree = [0] * len(nodes)
    parent = list(range(len(nodes)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b, _ in edges:
        if a is None:
            continue
        degree[a] += 1
        degree[b] += 1
        parent[find(a)] = find(b)
    components = {}
    for idx, (a, b, pts) in enumerate(edges):
        key = ("self", idx) if a is None else find(a)
        components.setdefault(key, []).append(idx)
    loops = 0
    areas = []
    for key, members in components.items():
        if key[0] == "self" if isinstance(key, tuple) else False:
            loops += 1
            areas.append((abs(Polygon(edges[members[0]][2]).area), slack[members[0]][1] + fitted_area(members)))
            continue
        comp_nodes = {n for m in members for n in edges[m][:2]}
        if all(degree[n] == 2 for n in comp_nodes):
            loops += 1
            # Walk the loop to order its points.
            ring = walk(members, edges)
            perimeter = sum(math.dist(ring[i], ring[i + 1]) for i in range(len(ring) - 1))
            snapped = sum(2 * spread[n] for n in comp_nodes) * perimeter
            areas.append((abs(Polygon(ring).area) if len(ring) >= 3 else 0.0,
                          sum(slack[m][1] for m in members) + snapped + fitted_area(members)))
    odd = sum(1 for d in degree if d % 2 == 1)
    print(json.dumps({"entities": counts, "length": length, "components": len(components), "loops": loops,
                      "loop_areas": [a for a, _ in sorted(areas)],
                      "loop_area_slack": [x for _, x in sorted(areas)], "length_slack": sum(x for x, _ in slack) + 4 * sum(spread) + 2e-6 * sum(fitted),
                      "odd_nodes": odd,
                      "branch_nodes": sum(1 for d in degree if d > 2)}))


def expand_inserts(entities, depth=0):
    """The entities with every INSERT replaced by its block's entities (ezdxf's transforms),
    nested; DIMENSION and other entities that ezdxf could decompose are not contours."""
    for e in entities:
        if e.dxftype() == "INSERT" and depth < 16:
            e.dxf.layer = "0"
            yield from expand_inserts(e.virtual_entities(), depth + 1)
        else:
            yield e


def points_of(e):
    """Points along a primitive in WCS: true circles and ellipses, NURBS evaluated by ezdxf."""
    kind = e.dxftype()
    if kind == "LINE":
        return [(e.dxf.start.x, e.dxf.start.y), (e.dxf.end.x, e.dxf.end.y)]
    if kind in ("ARC", "CIRCLE"):
        return [(v.x, v.y) for v in e.flattening(SAGITTA)]
    if kind in ("ELLIPSE", "SPLINE"):
        return [(v.x, v.y) for v in e.flattening(SAGITTA)]
    return []


def walk(members, edges):
    remaining = list(members)
    a, b, pts = edges[remaining.pop(0)]
    ring = list(pts)
    at = b
    while remaining:
        for i, m in enumerate(remaining):
            x, y, q = edges[m]
            if x == at:
                ring.extend(q[1:])
                at = y
            elif y == at:
                ring.extend(list(reversed(q))[1:])
                at = x
            else:
                continue
            remaining.pop(i)
            break
        else:
            break
    return ring


if __name__ == "__main__":
    main()
