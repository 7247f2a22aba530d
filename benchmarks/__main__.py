"""Run every ``benchmarks/bench_*.py`` script in turn (``make bench``).

Extra arguments are passed to each script; ``python -m benchmarks bench_probability`` runs the
scripts whose name contains ``bench_probability`` only.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def main(argv: list[str]) -> int:
    here = Path(__file__).resolve().parent
    names = [a for a in argv if not a.startswith("-")]
    flags = [a for a in argv if a.startswith("-")]
    scripts = sorted(here.glob("bench_*.py"))
    if names:
        scripts = [s for s in scripts if any(n in s.stem for n in names)]
    status = 0
    for script in scripts:
        print(f"=== {script.name} ===", flush=True)
        rc = subprocess.call([sys.executable, str(script), *flags])
        status = status or rc
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
