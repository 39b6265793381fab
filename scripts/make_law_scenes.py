#!/usr/bin/env python3
"""Writes the example scenes of the contact laws (docs/laws.md, "Examples"):

    configs/mortar_wall_2d.json   a running-bond wall with `cohesive` mortar joints, gravity tilted sideways
    configs/bonded_beam_2d.json   a beam of disks bonded by `czm`, broken in three-point bending
    configs/wet_pile_3d.json      a column of wet spheres (`wet`) that stands as a steep pile

    python3 scripts/make_law_scenes.py              # all three, into configs/
    python3 scripts/make_law_scenes.py --dry wall   # the wall without mortar (to compare), to stdout
    python3 scripts/make_law_scenes.py --dry pile   # the pile with dry grains (to compare), to stdout

The masonry arch is scripts/masonry_arch.py. Seeded: the same scenes every time.
"""
import argparse
import json
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def write_scene(s, path):
    """The scene as JSON, one body per line (readable, diffable)."""
    lines = []
    for key, value in s.items():
        if key == "bodies":
            lines.append(' "bodies": [\n  ' + ",\n  ".join(json.dumps(b) for b in value) + "\n ]")
        else:
            lines.append(" " + json.dumps(key) + ": " + json.dumps(value))
    text = "{\n" + ",\n".join(lines) + "\n}\n"
    if path == "-":
        sys.stdout.write(text)
    else:
        with open(path, "w") as f:
            f.write(text)


def box(half_x, half_y):
    return [[-half_x, -half_y], [half_x, -half_y], [half_x, half_y], [-half_x, half_y]]


def mortar_wall(tilt_deg=45.0, courses=10, per_course=5, length=0.24, height=0.08, mortar=True):
    """Bricks 0.24 × 0.08 m in running bond (half bricks at the ends of every other course)
    on a floor, every joint (bed, head, and to the floor) a `cohesive` bond of area half the
    brick's height or length per contact point (2 points a joint), gravity turned by
    `tilt_deg` (a tilt test: the wall loaded sideways by its own weight). Without mortar:
    dry joints with the mortar's friction. Solved to 1e-8: a rigid bonded assembly is
    statically indeterminate, and a loose solve leaves self-equilibrated tensions that
    break bonds the exact solution does not load (docs/laws.md, `cohesive`)."""
    g, b = 9.81, math.radians(tilt_deg)
    bodies = [{"name": "floor", "fixed": True, "position": [0, -0.05],
               "contactors": [{"shape": "polygon", "vertices": box(1.5, 0.05), "group": "floor"}]}]
    width = per_course * length
    for c in range(courses):
        y = height * (c + 0.5)
        if c % 2 == 0:
            bricks = [(-width / 2 + length * (i + 0.5), length) for i in range(per_course)]
        else:
            bricks = ([(-width / 2 + length / 4, length / 2)] +
                      [(-width / 2 + length / 2 + length * (i + 0.5), length) for i in range(per_course - 1)] +
                      [(width / 2 - length / 4, length / 2)])
        for i, (x, l) in enumerate(bricks):
            bodies.append({"name": "brick_%d_%d" % (c, i), "material": "brick", "position": [round(x, 12), round(y, 12)],
                           "contactors": [{"shape": "polygon", "vertices": box(l / 2, height / 2), "group": "brick"}]})
    return {"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-3, "duration": 2.0},
            "gravity": [round(g * math.sin(b), 12), round(-g * math.cos(b), 12)],
            "materials": {"brick": {"density": 1800}},
            "laws": {"mortar": {"type": "cohesive", "tensile_strength": 1e4, "cohesion": 2e4, "friction": 0.6,
                                "area": height / 2} if mortar else {"type": "coulomb", "friction": 0.6}},
            "interactions": [{"groups": ["brick", "brick"], "law": "mortar"}, {"groups": ["brick", "floor"], "law": "mortar"}],
            "detection": {"alert": 1e-3}, "solver": {"type": "auto", "tolerance": 1e-8},
            "output": {"file": "mortar_wall_2d.h5" if mortar else "dry_wall_2d.h5", "every": 20}, "bodies": bodies}


def bonded_beam(nx=40, ny=5, r=0.005, speed=0.05):
    """Disks of radius 5 mm in a triangular lattice (40 and 39 a row, 5 rows), every
    touching pair a `czm` bond of area 2r; two fixed disks support it near its ends and a
    disk pushed down at mid-span loads it (three-point bending)."""
    bodies = []
    dx, dy = 2 * r, math.sqrt(3) * r
    length = (nx - 1) * dx
    for j in range(ny):
        shift = r if j % 2 else 0.0
        for i in range(nx - 1 if j % 2 else nx):
            bodies.append({"name": "g_%d_%d" % (j, i), "material": "grain",
                           "position": [round(-length / 2 + shift + i * dx, 12), round(r + j * dy, 12)],
                           "contactors": [{"shape": "disk", "radius": r, "group": "grain"}]})
    top = r + (ny - 1) * dy + r
    span = length - 4 * r
    for name, x in (("left_support", -span / 2), ("right_support", span / 2)):
        bodies.append({"name": name, "fixed": True, "position": [x, -r],
                       "contactors": [{"shape": "disk", "radius": r, "group": "tool"}]})
    bodies.append({"name": "loader", "material": "grain", "position": [0, top + r],
                   "contactors": [{"shape": "disk", "radius": r, "group": "tool"}]})
    kn, strength, energy = 1e10, 2e5, 20.0
    return {"format": "moreau-scene/1", "dimension": 2, "time": {"step": 1e-4, "duration": 0.15},
            "gravity": [0, -9.81], "materials": {"grain": {"density": 2500}},
            "laws": {"cement": {"type": "czm", "normal_stiffness": kn, "tangential_stiffness": kn / 2,
                                "normal_strength": strength, "shear_strength": strength, "mode_I_energy": energy,
                                "mode_II_energy": 2 * energy, "area": 2 * r, "friction": 0.5},
                     "contact": {"type": "coulomb", "friction": 0.5}},
            "interactions": [{"groups": ["grain", "grain"], "law": "cement"}, {"groups": ["grain", "tool"], "law": "contact"}],
            "drivers": [{"body": "loader", "velocity": [0, -speed], "angular_velocity": 0}],
            "detection": {"alert": 1e-3}, "solver": {"type": "auto"},
            "output": {"file": "bonded_beam_2d.h5", "every": 10}, "bodies": bodies}


def wet_pile(wet=True, n=5, layers=10, r=0.005, seed=1):
    """A column of n × n × layers spheres (radius 5 mm, 2 % apart, shifted by up to 1 % of
    r at random, seeded) on a rough floor, released. Wet: bridges of 15 mN (about the
    weight of a sphere, 12.8 mN) within 0.5 mm."""
    rnd = random.Random(seed)
    bodies = [{"name": "floor", "fixed": True, "position": [0, 0, 0],
               "contactors": [{"shape": "plane", "normal": [0, 0, 1], "group": "floor"}]}]
    s = 2 * r * 1.02
    for k in range(layers):
        for j in range(n):
            for i in range(n):
                x = (i - (n - 1) / 2) * s + rnd.uniform(-0.01, 0.01) * r
                y = (j - (n - 1) / 2) * s + rnd.uniform(-0.01, 0.01) * r
                bodies.append({"name": "s_%d_%d_%d" % (k, j, i), "material": "glass",
                               "position": [round(x, 12), round(y, 12), round(r * 1.001 + k * s, 12)],
                               "contactors": [{"shape": "sphere", "radius": r, "group": "grain"}]})
    grains = ({"type": "wet", "adhesion": 0.015, "rupture_distance": 0.1 * r, "friction": 0.4} if wet
              else {"type": "coulomb", "friction": 0.4})
    return {"format": "moreau-scene/1", "dimension": 3, "time": {"step": 5e-4, "duration": 1.0},
            "gravity": [0, 0, -9.81], "materials": {"glass": {"density": 2500}},
            "laws": {"grains": grains, "floor": {"type": "coulomb", "friction": 0.6}},
            "interactions": [{"groups": ["grain", "grain"], "law": "grains"}, {"groups": ["grain", "floor"], "law": "floor"}],
            "detection": {"alert": 1e-3}, "solver": {"type": "auto"},
            "output": {"file": "wet_pile_3d.h5" if wet else "dry_pile_3d.h5", "every": 20}, "bodies": bodies}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--configs", default=os.path.join(HERE, "..", "configs"), help="folder to write into")
    p.add_argument("--dry", choices=["wall", "pile"], help="write the dry wall or pile to stdout instead")
    args = p.parse_args()
    if args.dry:
        write_scene(mortar_wall(mortar=False) if args.dry == "wall" else wet_pile(wet=False), "-")
        return 0
    write_scene(mortar_wall(), os.path.join(args.configs, "mortar_wall_2d.json"))
    write_scene(bonded_beam(), os.path.join(args.configs, "bonded_beam_2d.json"))
    write_scene(wet_pile(), os.path.join(args.configs, "wet_pile_3d.json"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
