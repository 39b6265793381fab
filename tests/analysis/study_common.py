"""What the study scripts share: their arguments, running a config, and the checks' tally."""
import os
import subprocess
import sys


class Study:
    """usage: SCRIPT SOURCE_DIR MOREAU WORK_DIR. Puts scripts/ on the path (plot_analyses)."""

    def __init__(self):
        self.src, self.moreau, self.work = sys.argv[1:4]
        sys.path.insert(0, os.path.join(self.src, "scripts"))
        os.makedirs(self.work, exist_ok=True)
        self.failures = []

    def run(self, config, out_name):
        out = os.path.join(self.work, out_name)
        subprocess.run([self.moreau, "run", os.path.join(self.src, "configs", config), "--out", out, "--quiet"], check=True)
        return out

    def check(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            self.failures.append(what)

    def plot(self, out, *args):
        """Runs scripts/plot_analyses.py OUT ARGS, figures into WORK/figures."""
        r = subprocess.run([sys.executable, os.path.join(self.src, "scripts", "plot_analyses.py"), out, *args,
                            "--out", os.path.join(self.work, "figures")], capture_output=True, text=True)
        print(r.stdout, end="")
        self.check(r.returncode == 0, "plot " + args[0] + (": " + r.stderr if r.returncode else ""))

    def finish(self):
        sys.exit(1 if self.failures else 0)
