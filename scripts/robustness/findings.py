#!/usr/bin/python3
"""Reproduces each input and fault finding of issue 11 (point 3) on a moreau binary and
prints a table: the finding, the exit code and the first line of what moreau printed, and
whether that is the promised outcome (docs/robustness.md).

usage: findings.py MOREAU [--plugins DIR] [--work DIR]

MOREAU    the executable (e.g. build/bin/moreau)
--plugins the folder of the test plugins that fail on purpose (default: the build's
          test-plugins/faults beside MOREAU's bin/)
--work    scratch folder (default: a temporary one)

Exits 1 if any finding is not as promised. Needs h5py (the restart and FCLib cases) and,
for the full-disk cases, the right to mount a tmpfs (else they are reported as skipped).
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.path.join(ROOT, "..", "shared", "fclib")

PROJECTILE = {
    "format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.01, "duration": 0.2}, "gravity": [0, -9.81],
    "bodies": [{"name": "ball", "position": [0, 1], "velocity": [2, 3], "angular_velocity": 1.5, "mass": 2.0,
                "inertia": 0.1},
               {"name": "wall", "fixed": True, "position": [1, 0]}],
    "output": {"file": "out.h5", "every": 5}}

rows = []


def run(args, cwd, env=None, limit_kb=None, timeout=600):
    cmd = [MOREAU] + args
    if limit_kb is not None:
        cmd = ["bash", "-c", 'ulimit -f %d; exec "$@"' % limit_kb, "run"] + cmd
    e = dict(os.environ, MOREAU_PLUGIN_PATH="")
    e.update(env or {})
    p = subprocess.run(cmd, cwd=cwd, env=e, capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stderr


def record(finding, code, err, want_code, want_text, extra_ok=True, note=""):
    signal_name = signal.Signals(-code).name if code < 0 else ""
    msg = next((l for l in err.splitlines() if want_text in l), err.strip().splitlines()[0] if err.strip() else "")
    ok = code == want_code and want_text in err and "internal error" not in err and extra_ok
    rows.append((finding, signal_name or str(code), msg[:150] + (" " + note if note else ""), "ok" if ok else "FAIL"))


def scene_file(d, name, text):
    p = os.path.join(d, name)
    with open(p, "w") as f:
        f.write(text)
    return p


def projectile_text(extra=""):
    t = json.dumps(PROJECTILE, indent=1)
    return t[:-2] + extra + "\n}" if extra else t


def scenes(work):
    d = os.path.join(work, "scene")
    os.makedirs(d)
    base = projectile_text()
    cases = [
        ("duplicated key accepted silently", base.replace('"mass": 2.0,', '"mass": 2.0, "mass": 20.0,'),
         'duplicate key "mass"'),
        ("1e400 escaped validation (internal error)", base.replace('"mass": 2.0', '"mass": 1e400'), "number out of range"),
        ("nesting 1e5 deep overflowed the stack",
         base.replace('"mass": 2.0', '"mass": ' + "[" * 100000 + "1" + "]" * 100000), "nested more than 64 levels"),
        ("output.file empty", base.replace('"file": "out.h5"', '"file": ""'), "expected a file name"),
    ]
    group = dict(PROJECTILE, laws={"l": {"type": "coulomb", "friction": 0.3}},
                 interactions=[{"groups": ["default", "default"], "law": "l"}])
    group["bodies"] = [{"name": "a", "mass": 1, "inertia": 1,
                        "contactors": [{"shape": "disk", "radius": 0.1, "group": 7}]},
                       {"name": "b", "mass": 1, "inertia": 1, "position": [1, 0],
                        "contactors": [{"shape": "disk", "radius": 0.1}]}]
    cases.append(("non-string group (internal error)", json.dumps(group), "expected a string, got an integer"))
    for i, (finding, text, want) in enumerate(cases):
        p = scene_file(d, "s%d.json" % i, text)
        code, err = run(["check", p], d)
        record("scene: " + finding, code, err, 2, p + ": at /")
        rows[-1] = rows[-1][:2] + (next((l for l in err.splitlines() if want in l), rows[-1][2]),) + \
            (rows[-1][3] if want in err else "FAIL",)
    # The mutated scenes that once crashed (SIGSEGV) or ended as internal error (exit 1).
    reg = os.path.join(ROOT, "tests", "fuzz", "regressions", "scene")
    outcomes = {}
    bad = 0
    for name in sorted(os.listdir(reg)):
        code, err = run(["check", os.path.join(reg, name)], d)
        outcomes[code] = outcomes.get(code, 0) + 1
        if code not in (0, 2) or "internal error" in err or (code == 2 and reg not in err):
            bad += 1
    rows.append(("scene: %d mutated scenes that crashed or were internal errors, `check`" % sum(outcomes.values()),
                 " ".join("exit %d x%d" % kv for kv in sorted(outcomes.items())), "", "ok" if bad == 0 else "FAIL"))
    sig = os.path.join(reg, "signal-03229-projectiles_2d.json")
    code, err = run(["run", sig, "--steps", "5", "--quiet", "--out", os.path.join(d, "sig.h5")], d)
    record("scene: the mutated scene that ended `run --steps 5` in SIGSEGV", code, err, 2, sig)


def damaged_fclib(d, name, src, dataset, edit):
    dst = os.path.join(d, name + ".hdf5")
    shutil.copy(os.path.join(SHARED, src), dst)
    with h5py.File(dst, "r+") as f:
        v = np.array(f[dataset][()], dtype=np.float64).reshape(-1)
        v = edit(v)
        del f[dataset]
        f[dataset] = v
    return dst


def fclib(work):
    d = os.path.join(work, "fclib")
    os.makedirs(d)
    local, glob = "fclib-local_problem_test.hdf5", None
    for n in sorted(os.listdir(SHARED)):
        if n.endswith(".hdf5") and glob is None and h5py.is_hdf5(os.path.join(SHARED, n)):
            with h5py.File(os.path.join(SHARED, n), "r") as f:
                if "fclib_global" in f:
                    glob = n

    def at(k, x):
        def e(v):
            v[k] = x
            return v
        return e

    cases = [
        ("NaN in q solved with exit 0", local, "/fclib_local/vectors/q", at(0, np.nan)),
        ("Inf in q gave converged, error 0", local, "/fclib_local/vectors/q", at(1, np.inf)),
        ("NaN in a CSR pointer array read out of bounds", local, "/fclib_local/W/p", at(1, np.nan)),
        ("m near 2^31 ended in bad_alloc (exit 1)", local, "/fclib_local/W/m", at(0, 2.0 ** 31 - 1), "/fclib_local/W"),
        ("n near 2^31", local, "/fclib_local/W/n", at(0, 2.0 ** 31)),
        ("NaN in mu", local, "/fclib_local/vectors/mu", at(0, np.nan)),
    ]
    if glob:
        cases.append(("Inf in w of a global problem", glob, "/fclib_global/vectors/w", at(0, -np.inf)))
        cases.append(("fraction in a CSC index of M", glob, "/fclib_global/M/i", at(0, 0.5)))
    for i, (finding, src, ds, edit, *where) in enumerate(cases):
        p = damaged_fclib(d, "f%d" % i, src, ds, edit)
        code, err = run(["fclib", "solve", p, "--solver", "nlgs", "--max-iter", "50"], d)
        record("fclib: " + finding, code, err, 2, p + ": at " + (where[0] if where else ds))


def leftovers(d):
    return sorted(os.path.relpath(os.path.join(r, n), d) for r, ds, fs in os.walk(d) for n in fs + ds
                  if n.endswith(".part") or n.endswith(".tmp") or n.endswith(".frames"))


def many_frames(d, duration=1.0):
    s = {"format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.001, "duration": duration},
         "gravity": [0, -9.81],
         "bodies": [{"name": "ball", "position": [0, 1], "velocity": [2, 3], "mass": 2.0, "inertia": 0.1}],
         "output": {"file": "out.h5", "every": 1}}
    return scene_file(d, "scene.json", json.dumps(s))


def faults(work):
    # File-size limits: wherever the limit strikes, exit 1 naming the file and the reason;
    # no temporary file; a frames folder only with the recovery command in the message.
    for kb in (4, 64, 400):
        d = os.path.join(work, "ulimit%d" % kb)
        os.makedirs(d)
        sc = many_frames(d)
        code, err = run(["run", sc, "--quiet"], d, limit_kb=kb)
        left = leftovers(d)
        frames_ok = all(not x.endswith(".frames") for x in left) or "--restart" in err
        parts = [x for x in left if not x.endswith(".frames")]
        record("fault: ulimit -f %d KiB (was SIGSEGV, .part left)" % kb, code, err, 1, "File too large",
               extra_ok=not parts and frames_ok, note="left: %s" % (left or "nothing"))
    # A full disk: a tmpfs of 2 MB and 8 MB.
    for size in ("2m", "8m"):
        d = os.path.join(work, "tmpfs" + size)
        os.makedirs(d)
        if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", d], capture_output=True).returncode:
            rows.append(("fault: full disk, tmpfs %s" % size, "-", "skipped: cannot mount a tmpfs here", "skip"))
            continue
        try:
            sc = many_frames(d, duration=20.0)
            code, err = run(["run", sc, "--quiet"], d)
            left = leftovers(d)
            parts = [x for x in left if not x.endswith(".frames")]
            frames_ok = all(not x.endswith(".frames") for x in left) or "--restart" in err
            record("fault: full disk, tmpfs %s (was SIGSEGV)" % size, code, err, 1, "No space left on device",
                   extra_ok=not parts and frames_ok, note="left: %s" % (left or "nothing"))
        finally:
            subprocess.run(["umount", d])
    # Plugins.
    d = os.path.join(work, "plugins")
    os.makedirs(d)
    pl = ',\n "plugin_paths": ["%s"],\n' % PLUGINS
    for name, cmd, want_code, want in [
        ("ctorthrow", "run", 2, "failed while it was being created"),
        ("ctorthrow42", "run", 2, "threw an exception that is not a std::exception"),
        ("schemathrow", "check", 2, "failed to register its plugins"),
        ("staticthrow", "check", 2, "threw while it was being loaded"),
        ("unresolved", "run", 2, "undefined symbol"),
    ]:
        p = scene_file(d, name + ".json", projectile_text(pl + ' "forces": [{"type": "%s"}]' % name))
        code, err = run([cmd, p, "--quiet"] if cmd == "run" else [cmd, p], d)
        record("plugin: force '%s' (%s)" % (name, cmd), code, err, want_code, want)
    for what, want_code, want in [("run_error", 1, "the run cannot go on"), ("int", 1, "not a std::exception"),
                                  ("own", 1, "own error class")]:
        p = scene_file(d, "hook_" + what + ".json",
                       projectile_text(pl + ' "hooks": [{"type": "throwing", "throw": "%s"}]' % what))
        code, err = run(["run", p, "--quiet"], d)
        record("plugin: hook throws %s during a run (was SIGSEGV)" % what, code, err, want_code, want)
    p = scene_file(d, "energy.json", projectile_text(',\n "hooks": [{"type": "energy_log", "file": "no/such/e.csv"}]'))
    code, err = run(["run", p, "--quiet"], d)
    record("plugin: energy_log given an unwritable file (was SIGSEGV)", code, err, 1, "energy_log: cannot write")
    p = scene_file(d, "missing.json", projectile_text(',\n "plugin_paths": ["my_plugins"]'))
    code, err = run(["check", p], d)
    record("plugin: missing plugin_paths folder (was ignored)", code, err, 2, "no folder")
    p = scene_file(d, "plain.json", projectile_text())
    code, err = run(["check", p], d, env={"MOREAU_PLUGIN_PATH": "/no/such/plugins"})
    record("plugin: missing MOREAU_PLUGIN_PATH folder (was ignored)", code, err, 0, "warning: MOREAU_PLUGIN_PATH")
    # A second run on the same output.
    d = os.path.join(work, "lock")
    os.makedirs(d)
    sc = many_frames(d, duration=200.0)
    first = subprocess.Popen([MOREAU, "run", sc, "--quiet"], cwd=d, stderr=subprocess.DEVNULL,
                             env=dict(os.environ, MOREAU_PLUGIN_PATH=""))
    for _ in range(100):
        if os.path.exists(os.path.join(d, "out.h5.lock")):
            break
        time.sleep(0.1)
    code, err = run(["run", sc, "--quiet"], d)
    alive = first.poll() is None
    first.send_signal(signal.SIGINT)
    first.wait()
    record("output: a second run on the same file (deleted the first's frames)", code, err, 2, "out.h5.lock",
           extra_ok=alive, note="" if alive else "(the first run had ended)")


def restart(work):
    d = os.path.join(work, "restart")
    os.makedirs(d)
    sc = os.path.join(ROOT, "configs", "box_tower_3d.json")
    with open(sc) as f:
        steps = json.load(f)
    assert run(["run", sc, "--out", "full.h5", "--quiet"], d)[0] == 0
    with h5py.File(os.path.join(d, "full.h5"), "r") as f:
        names = sorted(f["frames"].keys())
    mid = names[len(names) // 2]
    assert run(["run", sc, "--out", "part.h5", "--steps", str(int(mid)), "--quiet"], d)[0] == 0
    code, err = run(["run", sc, "--restart", "part.h5", "--out", "rest.h5", "--quiet"], d)
    diff = []
    with h5py.File(os.path.join(d, "full.h5"), "r") as a, h5py.File(os.path.join(d, "rest.h5"), "r") as b:
        for fr in sorted(b["frames"].keys()):
            def visit(n, o):
                if isinstance(o, h5py.Dataset):
                    x, y = a["frames/" + fr + "/" + n][()], o[()]
                    if x.shape != y.shape or not np.array_equal(x, y, equal_nan=True):
                        diff.append(fr + "/" + n)
            b["frames/" + fr].visititems(visit)
        contacts = "contacts" in b["frames/" + mid]
    rows.append(("restart: into a new file, every frame against the uninterrupted run (contacts differed)",
                 str(code), "first frame %s, contacts %s, %d datasets differ" % (mid, "present" if contacts else "ABSENT",
                                                                               len(diff)),
                 "ok" if code == 0 and not diff and contacts else "FAIL"))
    frame = "/frames/" + mid
    nodes = frame + "/rigid.nodes"  # moreau-output/2: /frames/N/orientation is a link to it

    def damage(name, dataset, edit):
        p = os.path.join(d, name + ".h5")
        shutil.copy(os.path.join(d, "part.h5"), p)
        with h5py.File(p, "r+") as f:
            v = np.array(f[dataset][()], dtype=np.float64)
            v = edit(v)
            del f[dataset]
            f[dataset] = v
        return p

    def put(idx, x):
        def e(v):
            v[idx] = x
            return v
        return e

    for name, ds, edit, want in [
        ("garbage contact keys (accepted)", frame + "/contacts/key", put((0, 0), 1e12), "is not a contact identity"),
        ("contact key naming contactor 999 (accepted)", frame + "/contacts/key", put((0, 1), 999), "names contactor"),
        ("NaN orientation (exit 1 mid-run)", nodes + "/orientation", put((1, 1), np.nan), "is not finite"),
        ("orientation not unit (accepted)", nodes + "/orientation", put((1, 0), 2.0), "not a unit quaternion"),
    ]:
        p = damage(name.split()[0] + name.split()[1], ds, edit)
        if os.path.exists(os.path.join(d, "r2.h5")):
            os.remove(os.path.join(d, "r2.h5"))
        code, err = run(["run", sc, "--restart", p, "--out", "r2.h5", "--quiet"], d)
        record("restart: " + name, code, err, 2, p + ": at " + ds, extra_ok=not os.path.exists(os.path.join(d, "r2.h5")))
        if want not in err:
            rows[-1] = rows[-1][:3] + ("FAIL",)


def main():
    global MOREAU, PLUGINS
    ap = argparse.ArgumentParser()
    ap.add_argument("moreau")
    ap.add_argument("--plugins")
    ap.add_argument("--work")
    a = ap.parse_args()
    MOREAU = os.path.abspath(a.moreau)
    PLUGINS = a.plugins or os.path.join(os.path.dirname(os.path.dirname(MOREAU)), "test-plugins", "faults")
    work = a.work or tempfile.mkdtemp(prefix="moreau-findings-")
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)
    for part in (scenes, fclib, faults, restart):
        part(work)
    w = max(len(r[0]) for r in rows)
    print("| finding | exit | message | |\n|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %s | %s |" % (r[0], r[1], r[2].replace("|", "\\|"), r[3]))
    bad = [r for r in rows if r[3] == "FAIL"]
    print("\n%d findings checked, %d as promised, %d not, %d skipped" %
          (len(rows), sum(r[3] == "ok" for r in rows), len(bad), sum(r[3] == "skip" for r in rows)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
