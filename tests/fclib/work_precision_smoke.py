"""Smoke test of scripts/work_precision.py (registered in tests/fclib/CMakeLists.txt): two
solvers on the smallest shared problem, one tolerance, one repeat, into a temp folder; the
table has the expected rows and the figures are non-empty PNGs. Bad input exits 2.

    python3 work_precision_smoke.py SOURCE_DIR MOREAU_EXE SHARED_DIR
"""
import csv
import os
import subprocess
import sys
import tempfile

try:
    import matplotlib  # noqa: F401
    import numpy  # noqa: F401
except ImportError as e:
    sys.exit(f"FAIL: {sys.executable} cannot import numpy and matplotlib ({e}); the benchmark script needs them "
             "(Debian: apt-get install python3-numpy python3-matplotlib, as scripts/setup.sh does)")

source, moreau, shared = sys.argv[1:4]
script = os.path.join(source, "scripts", "work_precision.py")
problem = os.path.join(shared, "fclib", "CubeH8.hdf5")
solvers = ["psor:relaxation=0.8", "newton"]
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def run(*args):
    return subprocess.run([sys.executable, script, *args], capture_output=True, text=True, timeout=300)


with tempfile.TemporaryDirectory() as out:
    p = run("--moreau", moreau, "--problems", problem, "--solvers", *solvers, "--tolerances", "1e-8",
            "--no-curves", "--repeat", "1", "--timeout", "60", "--out", out)
    if p.returncode != 0:
        sys.exit(f"FAIL: work_precision.py exited {p.returncode}\n{p.stdout}\n{p.stderr}")
    with open(os.path.join(out, "table.csv")) as f:
        rows = list(csv.DictReader(f))
    check([(r["problem"], r["solver"], r["tolerance"]) for r in rows] == [("CubeH8", s, "1e-8") for s in solvers],
          f"table.csv rows: {rows}")
    for r in rows:
        check(r["converged"] == "true" and float(r["error"]) <= 1e-8 and float(r["seconds"]) > 0,
              f"row not converged or malformed: {r}")
        check(int(r["iterations"]) >= 0, f"iterations: {r}")
    with open(os.path.join(out, "table.md")) as f:
        md = f.read()
    check("## Time to 1e-8 per problem against the Siconos reference" in md, "table.md lacks the reference section")
    check("| CubeH8 | `newton` |" in md, "table.md lacks the newton row")
    for png in ("error_vs_time_CubeH8.png", "profiles.png"):
        path = os.path.join(out, png)
        ok = os.path.isfile(path) and os.path.getsize(path) > 1000
        if ok:
            with open(path, "rb") as f:
                ok = f.read(8) == b"\x89PNG\r\n\x1a\n"
        check(ok, f"{png} missing, empty or not a PNG")

    # Bad input: a clear message and exit 2, before any run.
    for args, needle in ((["--moreau", os.path.join(out, "nothing"), "--problems", problem], "no moreau binary"),
                         (["--moreau", moreau, "--problems", os.path.join(out, "missing.hdf5")], "no problem file"),
                         (["--moreau", moreau, "--problems", problem, "--solvers", "psor:nonsense=1"], "nonsense")):
        b = run(*args, "--out", out)
        check(b.returncode == 2 and needle in b.stderr, f"{args}: exit {b.returncode}, stderr {b.stderr!r}")

if failures:
    sys.exit("FAIL:\n" + "\n".join(failures))
print("work_precision smoke test: ok")
