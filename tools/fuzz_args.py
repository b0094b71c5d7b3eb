#!/usr/bin/env python
"""Fuzz the command line's arguments and paths (the subcommands a user reaches, their FILE and --out).

tools/fuzz_specs.py mutates what a specification says; this campaign mutates what a command is given: FILE missing,
a folder, empty, a BOM alone, UTF-16, Latin-1 bytes, binary, NaN/inf/huge/negative numbers, unit strings, missing
sections; --out absent, an existing user file, a folder of user files (with and without --force), the folder of
FILE, FILE itself, a path under a file, the current folder, a kernel file system, an empty string; and the options of
each command set to NaN, inf, negative, zero, huge and text.  Each case runs in this process through click's test
runner, in a fresh temporary folder that is the current one, and is classified:

``ok``           exit status 0; every file there before is unchanged but the --out folder's own;
``refused``      exit status 2 (1 for an optimisation without a feasible point), the output its error lines alone,
                 each naming the option, the file or the key it is about, and nothing written or changed;
``traceback``    an exception the command did not handle;
``noise``        refused, with other lines before the error (a progress label, a note);
``bad_message``  refused with a line that names neither the option, the file nor a key;
``clobbered``    a file that was there before is changed or gone (the input, a user's file), or a refused command
                 left something behind (a folder, a temporary folder);
``nonsense``     exit status 0 and NaN or inf in a JSON file written;
``hang``         no answer within --timeout seconds.

Usage (from the repository root)::

    PYTHONPATH=src python tools/fuzz_args.py --count 400 --seed 1 --report fuzz-args.json

One process (the machine is shared): the cases run one after the other.
"""

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
from collections import Counter  # noqa: E402
import hashlib  # noqa: E402
import json  # noqa: E402
from pathlib import Path  # noqa: E402
import random  # noqa: E402
import re  # noqa: E402
import shutil  # noqa: E402
import signal  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
import traceback  # noqa: E402

from click.testing import CliRunner  # noqa: E402

from valvetrain.cli import main  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
APPENDIX = (ROOT / "examples" / "seed000-appendix-kurz.toml").read_text(encoding="utf-8")
MEASURED = (ROOT / "examples" / "measured-lobe.toml").read_text(encoding="utf-8")
TABLE = "data/measured-intake-lobe.csv"
assert TABLE in MEASURED
TOLERANCES = ('\n[[tolerances]]\nkey = "valves.intake.throat_diameter_mm"\ndistribution = "uniform"\n'
              'low = 37.19\nhigh = 37.21\n')
LIFT = "max_lift_mm = 10.0"
assert LIFT in APPENDIX

FILES = {
    "good": APPENDIX.encode(),
    "missing": None,
    "folder": "folder",
    "empty": b"",
    "bom_only": b"\xef\xbb\xbf",
    "bom": b"\xef\xbb\xbf" + APPENDIX.encode(),
    "utf16": APPENDIX.encode("utf-16"),
    "latin1": ("# r\u00e9gime\n" + APPENDIX).encode("latin-1"),
    "binary": bytes(range(256)) * 4,
    "engine_only": b"[engine]\n",
    "no_valves": APPENDIX.split("[valves")[0].encode(),
    "nan": APPENDIX.replace(LIFT, "max_lift_mm = nan").encode(),
    "inf": APPENDIX.replace(LIFT, "max_lift_mm = inf").encode(),
    "huge": APPENDIX.replace(LIFT, "max_lift_mm = 1e308").encode(),
    "negative": APPENDIX.replace(LIFT, "max_lift_mm = -10.0").encode(),
    "unit_string": APPENDIX.replace(LIFT, 'max_lift_mm = "10 mm"').encode(),
    "device": "/dev/zero",
    "table_folder": "table:folder",
    "table_empty": "table:empty",
    "table_device": "table:/dev/zero",
    "table_latin1": "table:latin1",
    "table_good": "table:good",
    "trailing_slash": "slash",
    "crlf": APPENDIX.replace("\n", "\r\n").encode(),
}

OUTS = ["fresh", "fresh", "user_file", "user_dir", "user_dir_force", "input_dir", "input_dir_force", "input_file",
        "under_file", "empty", "cwd_force", "proc", "deep", "previous", "newline"]

COMMANDS = {
    "run": ["run", "{file}", "--out", "{out}", "--figures", "none"],
    "validate": ["validate", "{file}"],
    "sweep": ["sweep", "{file}", "--out", "{out}"],
    "optimize": ["optimize", "{file}", "--out", "{out}", "--maxiter", "1", "--no-jump", "0"],
    "study": ["study", "{file}", "--grid", "engine.rated_speed_rpm=5000,5500", "--out", "{out}"],
    "tolerance": ["tolerance", "{file}", "--samples", "2", "--out", "{out}"],
    "compare": ["compare", "{file}", "{file}", "--out", "{out}"],
}

BAD_NUMBERS = ["nan", "inf", "-inf", "-1", "0", "1e308", "abc", "", "1e-300", "99999999999999999999999"]
OPTIONS = {
    "run": [("--lang", ["xx", ""]), ("--figures", ["some"])],
    "sweep": [("--valve", ["exhaust", "", "intake,intake"]), ("--lang", ["xx"])],
    "optimize": [("--valve", ["exhaust", ""]), ("--seed", BAD_NUMBERS), ("--maxiter", BAD_NUMBERS),
                 ("--cam-width", BAD_NUMBERS), ("--seating-velocity", BAD_NUMBERS),
                 ("--wheel-radius", BAD_NUMBERS), ("--objective", ["volumetric_efficiency", "torque", "x"]),
                 ("--vary", ["cam.phi1_deg=nan,30", "cam.phi1_deg=inf,30", "cam.phi1_deg=30,20", "=1,2", "x"])],
    "study": [("--workers", BAD_NUMBERS), ("--max-points", BAD_NUMBERS),
              ("--grid", ["engine.rated_speed_rpm=nan", "engine.rated_speed_rpm=inf,1", "engine.rated_speed_rpm=-1",
                          "engine.rated_speed_rpm=\"6000 rpm\"", "engine=1", "=", "valves.intake=1"])],
    "tolerance": [("--samples", BAD_NUMBERS), ("--seed", BAD_NUMBERS), ("--method", ["lhs", "sobol", "x"]),
                  ("--workers", BAD_NUMBERS), ("--max-samples", BAD_NUMBERS), ("--lang", ["xx"])],
    "compare": [],
    "validate": [],
}

SLOW = {"sweep", "optimize", "tolerance"}
"""Commands whose successful run takes long: drawn with bad options or paths mostly."""


def draw_case(rng):
    """One case: a command, a FILE variant, an --out variant and at most one option set to a drawn value."""
    command = rng.choice(list(COMMANDS))
    good = rng.random() < (0.15 if command in SLOW else 0.4)
    file = "good" if good else rng.choice(list(FILES))
    out = rng.choice(OUTS) if "{out}" in COMMANDS[command] else None
    option = None
    if OPTIONS[command] and (file == "good" and out in ("fresh", None) or rng.random() < 0.3):
        name, values = rng.choice(OPTIONS[command])
        option = [name, rng.choice(values)]
    return {"command": command, "file": file, "out": out, "option": option}


def _setup(case, tmp):
    """Write the case's files in ``tmp``; return the argument list and the paths the case names."""
    text = FILES[case["file"]]
    spec = tmp / "engine.toml"
    if isinstance(text, bytes):
        if case["command"] == "tolerance" and case["file"] == "good":
            text = text + TOLERANCES.encode()
        spec.write_bytes(text)
        file_arg = str(spec)
    elif text is None:
        file_arg = str(tmp / "absent.toml")
    elif text == "folder":
        (tmp / "specs").mkdir()
        file_arg = str(tmp / "specs")
    elif text == "/dev/zero":
        file_arg = text
    elif text.startswith("table:"):
        kind = text.removeprefix("table:")
        table = tmp / "lobe.csv"
        if kind == "folder":
            table.mkdir()
        elif kind == "empty":
            table.write_bytes(b"")
        elif kind == "latin1":
            table.write_bytes(("# lev\u00e9e\n" + (ROOT / "examples" / TABLE).read_text(encoding="utf-8"))
                              .encode("latin-1"))
        elif kind == "good":
            shutil.copy(ROOT / "examples" / TABLE, table)
        else:
            table = Path(kind)
        spec.write_text(MEASURED.replace(TABLE, str(table)), encoding="utf-8")
        file_arg = str(spec)
    else:
        spec.write_bytes(APPENDIX.encode())
        file_arg = str(spec) + "/"
    (tmp / "notes.txt").write_text("a user's own notes\n", encoding="utf-8")
    out = case["out"]
    out_arg = str(tmp / "out")
    if out == "user_file":
        (tmp / "out").write_text("a user's results\n", encoding="utf-8")
    elif out in ("user_dir", "user_dir_force"):
        (tmp / "out").mkdir()
        (tmp / "out" / "mine.txt").write_text("mine\n", encoding="utf-8")
    elif out in ("input_dir", "input_dir_force"):
        out_arg = str(tmp)
    elif out == "input_file":
        out_arg = file_arg
    elif out == "under_file":
        out_arg = str(tmp / "notes.txt" / "out")
    elif out == "empty":
        out_arg = ""
    elif out == "cwd_force":
        out_arg = "."
    elif out == "proc":
        out_arg = "/proc/valvetrain-out"
    elif out == "deep":
        out_arg = str(tmp / "a" / "b" / "c" / "out")
    elif out == "newline":
        out_arg = str(tmp / "out\nx")
    elif out == "previous":
        previous = tmp / "out"
        previous.mkdir()
        (previous / ".valvetrain-output").write_text("# written by valvetrain\nold.txt\n", encoding="utf-8")
        (previous / "old.txt").write_text("old\n", encoding="utf-8")
    args = [a.replace("{file}", file_arg).replace("{out}", out_arg) for a in COMMANDS[case["command"]]]
    if out is not None and out.endswith("_force"):
        args.append("--force")
    if case["option"]:
        name, value = case["option"]
        if name in args:
            args[args.index(name) + 1] = value
        else:
            args += [name, value]
    return args, file_arg, out_arg


def _snapshot(tmp):
    return {str(p.relative_to(tmp)): (hashlib.sha1(p.read_bytes()).hexdigest() if p.is_file() else "dir")
            for p in sorted(tmp.rglob("*"))}


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout


REFUSAL_LINE = re.compile(r"^(error: |Error: |Usage: |Try '|  )")
KEY = re.compile(r"(?<![\w.])(engine|valves|gas|crank|camshaft|breathing|output|accepted|tolerances)\b")


def _names_its_subject(line, file_arg, out_arg):
    return bool("--" in line or "'FILE'" in line or "FILE" in line or KEY.search(line)
                or (file_arg and file_arg.rstrip("/") in line) or (out_arg and out_arg in line)
                or "no such option" in line.lower() or not line.startswith(("error: ", "Error: ")))


def classify(case, result, before, after, file_arg, out_arg, out_was):
    """The outcome of a case and its detail."""
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        tb = "".join(traceback.format_exception(result.exception)[-3:])
        return "traceback", f"{type(result.exception).__name__}: {result.exception}"[:300], tb
    code = result.exit_code
    changed = [p for p, h in before.items() if after.get(p) != h and not _owned(p, case, code, out_arg)]
    if changed:
        return "clobbered", f"changed or gone: {changed[:5]}", ""
    if code != 0:
        new = [p for p in after if p not in before]
        if new:
            return "clobbered", f"refused (exit {code}) but left {new[:5]}", ""
        lines = [line for line in result.output.splitlines() if line.strip()]
        noise = [line for line in lines if not REFUSAL_LINE.match(line)]
        if noise:
            return "noise", f"before the error: {noise[:2]}", result.output[-600:]
        bad = [line for line in lines if not _names_its_subject(line, file_arg, out_arg)]
        if bad:
            return "bad_message", bad[0][:300], ""
        if code not in (1, 2) or (code == 1 and "error: " not in result.output):
            return "traceback", f"exit status {code}", result.output[-600:]
        return "refused", lines[-1][:200] if lines else "", ""
    temps = [p for p in after if ".valvetrain-" in p and p.endswith(".tmp")]
    if temps:
        return "clobbered", f"temporary folders left: {temps}", ""
    for path in Path(out_arg or ".").rglob("*.json") if out_arg and Path(out_arg).is_dir() else []:
        bad = []
        json.loads(path.read_text(encoding="utf-8"), parse_constant=bad.append)
        if bad:
            return "nonsense", f"{path.name} holds {bad[0]}", ""
    return "ok", "", ""


def _owned(rel, case, code, out_arg):
    """Whether a file's change is the command's own: under --out after a successful run that may replace it."""
    if code != 0 or not out_arg or case["out"] in ("user_file", "input_dir", "input_file", "under_file"):
        return False
    top = rel.split("/")[0]
    return top == "out" and case["out"] in ("previous", "user_dir_force", "fresh")


def run_case(case, timeout):
    tmp = Path(tempfile.mkdtemp(prefix="fuzzargs-"))
    cwd = os.getcwd()
    try:
        args, file_arg, out_arg = _setup(case, tmp)
        before = _snapshot(tmp)
        out_was = Path(out_arg).exists() if out_arg else False
        os.chdir(tmp)
        signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(int(timeout))
        start = time.monotonic()
        try:
            result = CliRunner().invoke(main, args)
        except Timeout:
            return {**case, "args": args, "outcome": "hang", "detail": f"over {timeout} s", "trace": ""}
        finally:
            signal.alarm(0)
            os.chdir(cwd)
        after = _snapshot(tmp)
        outcome, detail, trace = classify(case, result, before, after, file_arg, out_arg, out_was)
        return {**case, "args": [a.replace(str(tmp), "<tmp>") for a in args], "outcome": outcome,
                "detail": detail.replace(str(tmp), "<tmp>"), "trace": trace.replace(str(tmp), "<tmp>"),
                "seconds": round(time.monotonic() - start, 2)}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main_(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--seed", default="1")
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--report", default=None)
    ns = parser.parse_args(argv)
    rng = random.Random(ns.seed)
    records, counts = [], Counter()
    for i in range(ns.count):
        case = draw_case(rng)
        rec = run_case(case, ns.timeout)
        records.append(rec)
        counts[rec["outcome"]] += 1
        if rec["outcome"] not in ("ok", "refused"):
            print(f"[{i}] {rec['outcome']}: {rec['args']}: {rec['detail']}", file=sys.stderr, flush=True)
        if ns.report:
            Path(ns.report).write_text(json.dumps({"counts": counts, "cases": records}, indent=1), encoding="utf-8")
    print(dict(counts))
    return 0 if set(counts) <= {"ok", "refused"} else 1


if __name__ == "__main__":
    sys.exit(main_())
