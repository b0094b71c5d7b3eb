"""What the fuzz tests share: the fuzzers of tools/ (fuzz_specs, fuzz_bounds: one copy of the mutations and of the
checks), their hypothesis settings and the contract every case is held to."""

from pathlib import Path
import sys

from hypothesis import HealthCheck, Phase, note, settings

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))
import fuzz_bounds  # noqa: E402 (tools/, put on the path above)
import fuzz_specs as fuzz  # noqa: E402

__all__ = ["BASES", "FUZZ", "assert_contract", "fuzz", "fuzz_bounds"]

BASES = fuzz.base_specs()
"""The shipped examples the cases mutate, read once."""

FUZZ = settings(deadline=None, derandomize=True, database=None, phases=[Phase.explicit, Phase.generate],
                suppress_health_check=list(HealthCheck))
"""No shrinking (it would rerun designs for minutes): the generator draws one operation most of the time, and a
failure prints its base specification and mutations; derandomized, with no example database, so CI sees the same
cases every time."""


def assert_contract(case, timeout):
    """The case runs to finite, plausible results or is refused naming its keys; else the failure with its base
    specification and mutations.  ``timeout`` [s] of one run."""
    rec = fuzz.run_case(case, BASES, timeout=timeout)
    text = "\n".join([f"{rec['outcome']}: {rec.get('signature', '')}", f"base specification: {case['base']}"]
                     + [f"mutation: {d}" for d in rec["mutation"]] + rec.get("detail", []))
    note(text)
    assert rec["outcome"] in ("ok", "refused"), text
