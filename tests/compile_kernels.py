"""Compile the package's numba kernels into numba's cache before the test workers start (``tests/conftest.py``).

Every pytest-xdist worker would otherwise compile each kernel it meets first: in a fresh install (the CI's), 67 s of
processor time a worker, measured by designing the built-in example and six examples with an empty cache and again
with a full one (74.5 against 7.6 s).  ``python tests/compile_kernels.py dynamics`` compiles the elastic train's
kernels (the built-in example's design and its speed sweeps); ``python tests/compile_kernels.py stages`` those of the
cam laws, the breathing and the hydraulic drive (examples designed without their ``[dynamics]`` sections, so that
it compiles none of the first's).  The two take about the same time (39 s of processor time each), so the
controller runs them side by side and the workers load every kernel from the cache.
"""

import os
from pathlib import Path
import sys
import tomllib

from valvetrain.design import run
from valvetrain.specification import example_spec

EXAMPLES = Path(__file__).parents[1] / "examples"
STAGES = ("marine-hydraulic-exhaust", "tcc3-motored", "seed000-polydyne", "modern-dohc-roller-finger",
          "lost-motion-intake")
"""Examples whose designs meet the kernels of the cam laws, the breathing and the hydraulic drive."""


def compile_stages() -> None:
    os.chdir(EXAMPLES)                          # the examples name their tables relative to their folder
    for name in STAGES:
        document = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
        for valve in document.get("valves", {}).values():
            valve.pop("dynamics", None)
        run(document)


if __name__ == "__main__":
    {"dynamics": lambda: run(example_spec()), "stages": compile_stages}[sys.argv[1]]()
