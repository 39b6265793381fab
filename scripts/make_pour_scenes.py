#!/usr/bin/env python3
"""Writes the poured-grain example scenes of configs/ (deterministic: seeded).

    /usr/bin/python3 scripts/make_pour_scenes.py                 # all of them, into configs/
    /usr/bin/python3 scripts/make_pour_scenes.py --out DIR silo_2d.json   # some, elsewhere
"""
import argparse
import json
import math
import random
import sys
from pathlib import Path

CONFIGS = Path(__file__).resolve().parent.parent / "configs"


def disks_in_box_2d(n_x=12, n_y=16, radius=0.01, seed=1):
    rng = random.Random(seed)
    width = n_x * 2.5 * radius
    bodies = [
        {"name": "floor", "fixed": True, "position": [0, -0.005], "angle": 0,
         "contactors": [{"shape": "segment", "length": width + 0.02, "thickness": 0.01, "group": "wall"}]},
        {"name": "left", "fixed": True, "position": [-width / 2 - 0.005, 0.4], "angle": 1.5707963267948966,
         "contactors": [{"shape": "segment", "length": 0.8, "thickness": 0.01, "group": "wall"}]},
        {"name": "right", "fixed": True, "position": [width / 2 + 0.005, 0.4], "angle": 1.5707963267948966,
         "contactors": [{"shape": "segment", "length": 0.8, "thickness": 0.01, "group": "wall"}]},
    ]
    k = 0
    for j in range(n_y):
        for i in range(n_x):
            r = radius * rng.uniform(0.8, 1.0)
            x = -width / 2 + (i + 0.5) * 2.5 * radius + rng.uniform(-0.2, 0.2) * radius
            y = 0.05 + j * 2.5 * radius
            bodies.append({"name": f"d{k}", "material": "grain", "position": [round(x, 6), round(y, 6)],
                           "velocity": [round(rng.uniform(-0.1, 0.1), 4), 0],
                           "contactors": [{"shape": "disk", "radius": round(r, 6), "group": "grain"}]})
            k += 1
    return {
        "format": "moreau-scene/1",
        "dimension": 2,
        "time": {"step": 5e-4, "duration": 1.0, "theta": 0.5},
        "gravity": [0, -9.81],
        "materials": {"grain": {"density": 2600}},
        "laws": {"grain_grain": {"type": "coulomb", "friction": 0.3},
                 "grain_wall": {"type": "coulomb", "friction": 0.5}},
        "bodies": bodies,
        "interactions": [{"groups": ["grain", "grain"], "law": "grain_grain"},
                         {"groups": ["grain", "wall"], "law": "grain_wall"}],
        "detection": {"broadphase": "grid", "alert": 0.002},
        "output": {"file": "disks_in_box_2d.h5", "every": 40},
    }


def spheres_in_box_3d(n=6, layers=8, radius=0.01, seed=2):
    rng = random.Random(seed)
    half = n * 2.5 * radius / 2
    planes = [("floor", [0, 0, 0], [0, 0, 1]), ("x0", [-half, 0, 0], [1, 0, 0]), ("x1", [half, 0, 0], [-1, 0, 0]),
              ("y0", [0, -half, 0], [0, 1, 0]), ("y1", [0, half, 0], [0, -1, 0])]
    bodies = [{"name": name, "fixed": True, "position": p,
               "contactors": [{"shape": "plane", "normal": nrm, "group": "wall"}]} for name, p, nrm in planes]
    k = 0
    for l in range(layers):
        for j in range(n):
            for i in range(n):
                x = -half + (i + 0.5) * 2.5 * radius + rng.uniform(-0.2, 0.2) * radius
                y = -half + (j + 0.5) * 2.5 * radius + rng.uniform(-0.2, 0.2) * radius
                z = 0.03 + l * 2.5 * radius
                bodies.append({"name": f"s{k}", "material": "grain", "position": [round(x, 6), round(y, 6), round(z, 6)],
                               "contactors": [{"shape": "sphere", "radius": round(radius * rng.uniform(0.85, 1.0), 6),
                                               "group": "grain"}]})
                k += 1
    return {
        "format": "moreau-scene/1",
        "dimension": 3,
        "time": {"step": 5e-4, "duration": 0.4, "theta": 0.5},
        "gravity": [0, 0, -9.81],
        "materials": {"grain": {"density": 2600}},
        "laws": {"grain_grain": {"type": "coulomb", "friction": 0.3},
                 "grain_wall": {"type": "coulomb", "friction": 0.3}},
        "bodies": bodies,
        "interactions": [{"groups": ["grain", "grain"], "law": "grain_grain"},
                         {"groups": ["grain", "wall"], "law": "grain_wall"}],
        "detection": {"broadphase": "grid", "alert": 0.002},
        "output": {"file": "spheres_in_box_3d.h5", "every": 40},
    }


def silo_2d(columns=20, rows=30, seed=4):
    """A flat silo discharging through a hopper: disks of radius 3-4 mm between two walls
    0.5 m tall (segments far longer than a grain: the grid broad phase keeps them out of its
    cell size), two hopper walls down to an orifice of five diameters, a floor below."""
    rng = random.Random(seed)
    r_max, width, pitch = 0.004, 0.2, 0.01
    half = width / 2
    t = 0.01  # wall thickness
    hop = [half, 0.1, 0.02, 0.03]  # hopper wall from (x0, y0) down to the orifice edge (x1, y1)
    hop_len = math.hypot(hop[0] - hop[2], hop[1] - hop[3])
    hop_angle = math.atan2(hop[1] - hop[3], hop[0] - hop[2])
    bodies = [
        {"name": "left", "fixed": True, "position": [-half - t / 2, 0.35], "angle": math.pi / 2,
         "contactors": [{"shape": "segment", "length": 0.5, "thickness": t, "group": "wall"}]},
        {"name": "right", "fixed": True, "position": [half + t / 2, 0.35], "angle": math.pi / 2,
         "contactors": [{"shape": "segment", "length": 0.5, "thickness": t, "group": "wall"}]},
        {"name": "hopper_left", "fixed": True, "position": [-(hop[0] + hop[2]) / 2, (hop[1] + hop[3]) / 2],
         "angle": round(-hop_angle, 12), "contactors": [{"shape": "segment", "length": round(hop_len, 9), "thickness": t,
                                                          "group": "wall"}]},
        {"name": "hopper_right", "fixed": True, "position": [(hop[0] + hop[2]) / 2, (hop[1] + hop[3]) / 2],
         "angle": round(hop_angle, 12), "contactors": [{"shape": "segment", "length": round(hop_len, 9), "thickness": t,
                                                         "group": "wall"}]},
        {"name": "floor", "fixed": True, "position": [0, -0.25], "angle": 0,
         "contactors": [{"shape": "segment", "length": 0.8, "thickness": t, "group": "wall"}]},
    ]
    k = 0
    for j in range(rows):
        for i in range(columns):
            x = -half + (i + 0.5) * pitch + rng.uniform(-0.1, 0.1) * r_max
            y = 0.12 + j * pitch
            bodies.append({"name": f"g{k}", "material": "grain", "position": [round(x, 6), round(y, 6)],
                           "contactors": [{"shape": "disk", "radius": round(r_max * rng.uniform(0.75, 1.0), 6),
                                           "group": "grain"}]})
            k += 1
    return {
        "format": "moreau-scene/1",
        "dimension": 2,
        "time": {"step": 5e-4, "duration": 1.5, "theta": 0.5},
        "gravity": [0, -9.81],
        "materials": {"grain": {"density": 2600}},
        "laws": {"grain_grain": {"type": "coulomb", "friction": 0.4},
                 "grain_wall": {"type": "coulomb", "friction": 0.4}},
        "bodies": bodies,
        "interactions": [{"groups": ["grain", "grain"], "law": "grain_grain"},
                         {"groups": ["grain", "wall"], "law": "grain_wall"}],
        "detection": {"broadphase": {"type": "grid"}, "alert": 0.001},
        "output": {"file": "silo_2d.h5", "every": 40},
    }


def unit_quaternion(rng):
    """A random rotation (uniform on SO(3), Shoemake), rounded yet unit to 1e-9."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    q = [a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2), b * math.sin(2 * math.pi * u3),
         b * math.cos(2 * math.pi * u3)]
    return [round(x, 12) for x in q]


def clusters_3d(n=4, layers=4, radius=0.01, seed=3):
    """Dumbbells and tetrahedral clusters of spheres (several contactors on one body, each at
    an offset in the body frame), turned at random and poured into a box."""
    rng = random.Random(seed)
    pitch = 5 * radius
    half = n * pitch / 2
    planes = [("floor", [0, 0, 0], [0, 0, 1]), ("x0", [-half, 0, 0], [1, 0, 0]), ("x1", [half, 0, 0], [-1, 0, 0]),
              ("y0", [0, -half, 0], [0, 1, 0]), ("y1", [0, half, 0], [0, -1, 0])]
    bodies = [{"name": name, "fixed": True, "position": p,
               "contactors": [{"shape": "plane", "normal": nrm, "group": "wall"}]} for name, p, nrm in planes]
    # Sphere centres in the body frame, touching: the density-based mass and inertia of a
    # cluster are exact only for contactors that do not overlap.
    d = radius
    dumbbell = [[-d, 0, 0], [d, 0, 0]]
    t = 2 * d / math.sqrt(8 / 3)  # tetrahedron of edge 2d around its centre
    tetra = [[t * x, t * y, t * z] for x, y, z in
             [(math.sqrt(8 / 9), 0, -1 / 3), (-math.sqrt(2 / 9), math.sqrt(2 / 3), -1 / 3),
              (-math.sqrt(2 / 9), -math.sqrt(2 / 3), -1 / 3), (0, 0, 1)]]
    k = 0
    for l in range(layers):
        for j in range(n):
            for i in range(n):
                x = -half + (i + 0.5) * pitch + rng.uniform(-0.2, 0.2) * radius
                y = -half + (j + 0.5) * pitch + rng.uniform(-0.2, 0.2) * radius
                z = 0.03 + l * pitch
                kind = dumbbell if (i + j + l) % 2 == 0 else tetra
                bodies.append({"name": f"{'dumbbell' if kind is dumbbell else 'tetra'}{k}", "material": "grain",
                               "position": [round(x, 6), round(y, 6), round(z, 6)], "orientation": unit_quaternion(rng),
                               "contactors": [{"shape": "sphere", "radius": radius, "offset": [round(c, 9) for c in o],
                                               "group": "grain"} for o in kind]})
                k += 1
    return {
        "format": "moreau-scene/1",
        "dimension": 3,
        "time": {"step": 5e-4, "duration": 0.5, "theta": 0.5},
        "gravity": [0, 0, -9.81],
        "materials": {"grain": {"density": 2600}},
        "laws": {"grain_grain": {"type": "coulomb", "friction": 0.4},
                 "grain_wall": {"type": "coulomb", "friction": 0.3}},
        "bodies": bodies,
        "interactions": [{"groups": ["grain", "grain"], "law": "grain_grain"},
                         {"groups": ["grain", "wall"], "law": "grain_wall"}],
        "detection": {"broadphase": "grid", "alert": 0.002},
        "output": {"file": "clusters_3d.h5", "every": 40},
    }


def scenes():
    default = disks_in_box_2d()
    default["output"]["file"] = "default.h5"
    return {"disks_in_box_2d.json": disks_in_box_2d(), "spheres_in_box_3d.json": spheres_in_box_3d(),
            "clusters_3d.json": clusters_3d(), "silo_2d.json": silo_2d(), "default.json": default}


def main(argv):
    all_scenes = scenes()
    parser = argparse.ArgumentParser(description="Writes the poured-grain example scenes (seeded: the same files "
                                                 "every time). Without arguments: all of them, into configs/.")
    parser.add_argument("names", nargs="*", metavar="NAME", help="scenes to write (default: all): " +
                        ", ".join(all_scenes))
    parser.add_argument("--out", type=Path, default=CONFIGS, help="folder to write into (default: configs/)")
    args = parser.parse_args(argv)
    unknown = [n for n in args.names if n not in all_scenes]
    if unknown:
        parser.error("unknown scene " + ", ".join(unknown) + "; valid: " + ", ".join(all_scenes))
    args.out.mkdir(parents=True, exist_ok=True)
    for name in args.names or all_scenes:
        (args.out / name).write_text(json.dumps(all_scenes[name], indent=1) + "\n")
        print("wrote", args.out / name)


if __name__ == "__main__":
    main(sys.argv[1:])
