"""Shared fixtures: the cam of the appendix of Valve-train practical works (n.d.); a specification refused by the
command line; the system's chromium for the browser tests (pytest-playwright)."""

import os
from pathlib import Path
import shutil
import subprocess
import sys

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main

from valvetrain.dynamics.sweep import kernels_cached
from valvetrain.laws import KurzLaw


@pytest.hookimpl(tryfirst=True)
def pytest_sessionstart(session):
    """With two or more pytest-xdist workers and the kernels not in numba's cache (a fresh install), compile them
    once, in two processes side by side, before the workers start (``compile_kernels.py``): otherwise each worker
    compiles them again."""
    config = session.config
    if hasattr(config, "workerinput") or len(getattr(config.option, "tx", None) or []) < 2 or kernels_cached():
        return
    script = Path(__file__).with_name("compile_kernels.py")
    jobs = [subprocess.Popen([sys.executable, str(script), part], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             text=True) for part in ("dynamics", "stages")]
    for job in jobs:
        _, err = job.communicate()
        if job.returncode != 0:
            raise pytest.UsageError(f"compiling the kernels before the tests failed:\n{err}")


SEED000_OMEGA_EXACT = np.pi * 3500 / 30
"""Camshaft speed of the appendix of Valve-train practical works (n.d.), pi n_cam / 30 [rad/s]."""

SEED000_OMEGA_TABLE = 366.5
"""The rounded camshaft speed with which Table P1 of Valve-train practical works (n.d.) was computed (spec, section 4)."""


def seed000_law():
    """The Kurz cam of the appendix of Valve-train practical works (n.d.): h_T max 6.25 mm, h0 0.25 mm, w' 0.02 mm/deg, 27/6/38 deg."""
    return KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27.0, 6.0, 38.0]), 0.625)


def sampled_kurz(shift_deg=0.0, noise=0.0, step_deg=1.0):
    """The lift of :func:`seed000_law` sampled every ``step_deg`` cam deg over +-92 deg, its origin moved by
    ``shift_deg``, with normal noise of ``noise`` [m] (seed 7): ``(law, theta [rad], lift [m])``, a measured table's
    stand-in."""
    law = seed000_law()
    theta = np.radians(np.arange(-92.0, 92.01, step_deg))
    lift = law.lift(theta) + np.random.default_rng(7).normal(0.0, noise, theta.size)
    return law, theta + np.radians(shift_deg), lift


@pytest.fixture
def kurz_appendix():
    return seed000_law()


@pytest.fixture
def refused(tmp_path):
    """``refused(text, command="validate")``: write ``text`` as a specification in ``tmp_path``, run the command
    on it, check exit status 2 and that no output folder was made; return the printed messages."""
    def check(text, command="validate"):
        f = tmp_path / "spec.toml"
        f.write_text(text)
        out = tmp_path / "out"
        result = CliRunner().invoke(main, [command, str(f)] + (["--out", str(out)] if command in ("run", "sweep") else []))
        assert result.exit_code == 2, result.output
        assert not out.exists()
        return result.output
    return check


def plain(x):
    """Numbers, text, arrays and containers of them: what a figure's data may hold (no design object)."""
    if isinstance(x, dict):
        return all(isinstance(k, str) and plain(v) for k, v in x.items())
    if isinstance(x, (list, tuple)):
        return all(plain(v) for v in x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind in "biufU"
    return x is None or isinstance(x, (str, bool, int, float, np.floating))


BROWSER = shutil.which("chromium") or shutil.which("chromium-headless-shell")
"""The browser of the browser tests: Debian's chromium (``executable_path``: a downloaded browser build cannot be had
here)."""


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args):
    """pytest-playwright's launch arguments with the system's chromium; without one the browser tests are skipped,
    except in CI (``CI=true``), where a missing browser fails them."""
    if BROWSER is None:
        if os.environ.get("CI") == "true":
            pytest.fail("no chromium on this machine: .ci/run installs the Debian package `chromium`")
        pytest.skip("no chromium on this machine (apt-get install -y chromium)")
    return {**browser_type_launch_args, "executable_path": BROWSER, "args": BROWSER_ARGS}


BROWSER_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--no-first-run"]
"""The browser's switches: headless on a machine without a sandbox or a GPU, nothing fetched from the network."""
