"""Command line: ``valvetrain run | sweep | optimize | study | tolerance | validate | compare | serve | example``.

Exit status: 0 on success, 2 for a specification or an output folder that cannot be used
(one message per problem on standard error; nothing is written), 130 when interrupted
(Ctrl-C), 1 for any other failure.  A design whose checks fail -- warnings, and failures
such as a stress above its allowable -- is a result, not an error: ``run`` and ``validate``
print the open checks, ranked, and the verdict, and exit 0; with ``--strict`` they exit 1
when a failure is open (not accepted in the specification).
"""

import gc
import itertools
import signal
import sys
import time

import click

from . import __version__
from .errors import ValvetrainError
from .interruption import Interruption, end_interrupted
from .outfolder import OutFolderError, check_out, location_problem, out_path
from .specification import SpecError, example_spec, example_text, input_files, load_spec

OUT_HELP = ("Folder for the results: new, empty, or a previous valvetrain output, which is replaced "
            "atomically; a folder with other files is refused unless --force.")
FORCE_HELP = "Replace --out even if it holds files that valvetrain did not write (never the input files)."


def _fail_spec(err):
    for problem in err.problems:
        click.echo(f"error: {problem}", err=True)
    sys.exit(2)


def _load(path):
    try:
        return load_spec(path) if path else example_spec()
    except SpecError as err:
        _fail_spec(err)


def _fail_out(err):
    click.echo(f"error: --out {err}", err=True)
    sys.exit(2)


def _check_out(out, files, specs, force):
    """Refuse an unusable --out before the design is computed; return the files the run reads."""
    inputs = [*files, *(f for spec in specs for f in input_files(spec))]
    try:
        check_out(out, inputs, force)
    except OutFolderError as err:
        _fail_out(err)
    return inputs


def _design(spec, progress=None):
    """Run a design; a valid specification that admits no design (no spring fits) exits like a bad one."""
    from .design import run as run_design

    try:
        return run_design(spec, progress=progress)
    except SpecError as err:
        _fail_spec(err)


_BOUND = {"failure": "allowed", "warning": "recommended", "info": "usual"}


def _echo_checks(results):
    """The failed checks, ranked (failures, warnings, info; the farthest outside first), one line each; the accepted
    failures marked as such with their reasons; then the counts and the verdict (the report's words); returns the
    number of open failures."""
    for w in results.warnings:
        click.echo(f"{w.severity}: {w.statement}, {_BOUND[w.severity]} {w.range} "
                   f"({w.source})".replace("  ", " "))
    accepted = results.accepted
    for w in accepted:
        if w.severity == "failure":
            click.echo(f"accepted failure: {w.statement}, allowed {w.range} "
                       f"({w.source}); reason: {w.reason}".replace("  ", " "))
    from .checks import tally
    from .locale import verdict

    counts = tally(results.checks)
    sentence, numbers = verdict(counts)
    click.echo(numbers)
    click.echo(f"verdict: {sentence}")
    return counts["failure"]


def _strict_exit(open_failures, strict):
    """``--strict``: exit status 1 where a failure is open (not accepted in the specification)."""
    if strict and open_failures:
        sys.exit(1)


STRICT_HELP = ("Exit with status 1 when a failure is open (a failed limit not accepted in the specification), for "
               "use in CI; the outputs are written all the same.")


class _Range(click.FloatRange):
    """A bounded real option that refuses NaN too (click's own range lets NaN through: no comparison with it is
    true)."""

    def convert(self, value, param, ctx):
        number = super().convert(value, param, ctx)
        if number != number:
            self.fail(f"{number} is not in the range {self._describe_range()}.", param, ctx)
        return number


class _Progress:
    """``progress(name, done, total)`` of a long step (a speed sweep, the points of a study, the generations of an
    optimisation): a bar on standard error once the step promises to take more than :attr:`AFTER` seconds, on a
    terminal only, erased when the step ends.  A short step, a pipe or a file get nothing, and a command that then
    refuses its input prints its error lines alone."""

    AFTER = 1.0

    def __init__(self, what="speed sweep"):
        self.bar, self.start, self.shown, self.what = None, 0.0, 0, what

    def __call__(self, name, done, total):
        now = time.monotonic()
        if done == 0:
            self.close()
            self.start, self.shown = now, 0
            return
        if (self.bar is None and (now - self.start) * total / done > self.AFTER and done < total
                and sys.stderr.isatty()):
            self.bar = click.progressbar(length=total, label=f"{name}: {self.what}", file=sys.stderr)
            self.bar.__enter__()
        if self.bar is not None:
            self.bar.update(done - self.shown)
            self.shown = done
            if done >= total:
                self.close()

    def close(self):
        """Erase the bar (the line it was drawn on)."""
        if self.bar is not None:
            self.bar.file.write("\r\x1b[K")
            self.bar.file.flush()
            self.bar = None


class _Main(click.Group):
    """The command group; Ctrl-C ends any command with exit status 130 and one line, not a traceback, and an error
    valvetrain raised on purpose that the command did not handle (:class:`valvetrain.errors.ValvetrainError`) with
    exit status 1 and its one line, led by its key where it has one.

    The SIGINT handler (:class:`valvetrain.interruption.Interruption`) remembers the SIGINT, so that an error a library
    made of the KeyboardInterrupt is the interruption too."""

    def make_context(self, info_name, args, parent=None, **extra):
        """Parse the command line; Ctrl-C before or while parsing is the interruption too (click would say
        'Aborted!')."""
        Interruption.install(Interruption.interrupt)
        try:
            if Interruption.seen:
                raise KeyboardInterrupt
            return super().make_context(info_name, args, parent, **extra)
        except BaseException:
            if not Interruption.seen:
                raise
            end_interrupted()

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except ValvetrainError as err:
            if isinstance(err, SpecError) and not Interruption.seen:
                _fail_spec(err)
            if not Interruption.seen:
                click.echo(f"error: {err.key + ': ' if err.key else ''}{err}", err=True)
                sys.exit(1)
            end_interrupted()
        except Exception:
            if not Interruption.seen:
                raise
            end_interrupted()
        except KeyboardInterrupt:
            end_interrupted()


@click.group(cls=_Main, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="valvetrain")
def main() -> None:
    """Design calculation of engine valve trains.

    Start with `valvetrain example > my-engine.toml`, edit it, check it with
    `valvetrain validate my-engine.toml`, and run it with
    `valvetrain run my-engine.toml --out my-design`.
    """


@main.command()
@click.argument("file", required=False, type=click.Path(dir_okay=False))
@click.option("--out", "out", default="design", show_default=True, type=click.Path(), help=OUT_HELP)
@click.option("--force", is_flag=True, help=FORCE_HELP)
@click.option("--lang", type=click.Choice(["en", "ru"]), default="en", show_default=True,
              help="Language of the report and plots.")
@click.option("--figures", type=click.Choice(["main", "all", "none"]), default="main", show_default=True,
              help="Plots to draw: main (each valve's kinematics and cam contour, one figure of each further "
                   "stage: dynamics against speed, grinding, hydraulic drive, crank, camshaft and port figures; and "
                   "the timing diagram), all (also the time-area, curvature, spring, strength, dynamics maps, "
                   "hydraulic sweep, crank-force, crank-pin and port time-area figures), or none; the report embeds "
                   "those drawn.")
@click.option("--strict", is_flag=True, help=STRICT_HELP)
def run(file, out, force, lang, figures, strict) -> None:
    """Run the design of FILE (default: the built-in example) and write it to --out."""
    from .export import DRAWER_IMPORTS, write_outputs
    from .report.drawing import start

    spec = _load(file)
    inputs = _check_out(out, [file] if file else [], [spec], force)
    drawer = start(DRAWER_IMPORTS) if figures != "none" else None   # imports matplotlib while this process designs
    program = gc.get_freeze_count() > 0   # the program froze its imports (console); a caller's process is left alone
    if program:
        gc.freeze()   # the design's collections do not look through the modules imported so far
    try:
        results = _design(spec, _Progress())
        if program:
            gc.freeze()   # nor the writer's through the results
        write_outputs(results, out, lang, inputs, force, figures, drawer)
    except OutFolderError as err:
        _fail_out(err)
    finally:
        if drawer is not None:
            drawer.stop()
    click.echo(f"wrote {out}/ (results.json, report.html, tables/, plots/, contour/)")
    from .units import MM

    for name, v in results.valves.items():
        if v.profile.undercut:
            click.echo(f"refused: valves.{name}: the cam profile is undercut (rho_min = {v.profile.rho_min / MM:.4g}"
                       " mm): no contour, DXF or manufacturing table was written for it")
        if v.records.measured is not None:
            click.echo(f"note: valves.{name}: measured table fitted by the {v.records.measured.fit_reason}")
    _strict_exit(_echo_checks(results), strict)


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--out", "out", default="sweep", show_default=True, type=click.Path(), help=OUT_HELP)
@click.option("--valve", "valves", multiple=True, metavar="NAME",
              help="A valve to sweep (repeatable); default: the valves with a [dynamics] section, or all.")
@click.option("--force", is_flag=True, help=FORCE_HELP)
@click.option("--lang", type=click.Choice(["en", "ru"]), default="en", show_default=True, help="Language of the plots.")
def sweep(file, out, valves, force, lang) -> None:
    """Run only the speed sweep of the elastic valve train of FILE and write it to --out.

    Each valve's [valves.NAME.dynamics] section is used (its defaults where it has none): one-mass or
    multi-mass train, every speed of the range, jump, bounce and seating. Writes dynamics.json,
    tables/NAME_dynamics.csv and plots/NAME_dynamics_map.png, NAME_dynamics_speed.png."""
    from .design import sweep_designs
    from .design.dynamics_checks import CHECK_CODES
    from .export import write_sweep

    spec = _load(file)
    if not spec.valves:
        click.echo("error: the file defines no valves to sweep", err=True)
        sys.exit(2)
    inputs = _check_out(out, [file], [spec], force)
    progress = _Progress()
    try:
        designs = sweep_designs(spec, valves, progress)
    except SpecError as err:
        _fail_spec(err)
    finally:
        progress.close()
    try:
        write_sweep(designs, out, lang, inputs, force)
    except OutFolderError as err:
        _fail_out(err)
    for name, v in designs.items():
        d = v.dynamics
        click.echo(f"{name}: {_headline(d)}")
        for w in v.warnings:
            if w.code in CHECK_CODES:
                click.echo(f"{w.severity}: {w.statement}, {_BOUND[w.severity]} {w.range} ({w.source})")
    click.echo(f"wrote {out}/ (dynamics.json, tables/, plots/)")


def _headline(d):
    """One line of a sweep's headline numbers (engine rpm), the crossing speeds with their estimated errors."""
    from .units import to_display

    def rpm(x, error=None):
        if x != x:
            return "none in the range"
        return f"{to_display(x, 'rpm'):.0f}" + ("" if error is None or error != error else
                                                f" ± {to_display(error, 'rpm'):.2g}") + " rpm"

    r, a = d.at_rated_speed, d.accuracy
    return (f"jump {rpm(d.jump_speed, a.jump_speed)}, bounce onset {rpm(d.bounce_speed, a.bounce_speed)}, max seating "
            f"velocity {d.max_seating_velocity:.3g} m/s at {rpm(d.max_seating_velocity_speed)}; at the rated {rpm(r.speed)}: "
            f"min contact force {r.min_contact_force:.4g} N, seating velocity {r.seating_velocity:.3g} m/s, bounce "
            f"{r.bounce * 1e3:.3g} mm")


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--out", "out", default="optimum", show_default=True, type=click.Path(), help=OUT_HELP)
@click.option("--valve", default=None, metavar="NAME", help="The valve whose cam is optimised; default: the first.")
@click.option("--objective", type=click.Choice(["fullness", "time_area", "volumetric_efficiency", "torque"]),
              default="fullness", show_default=True,
              help="Maximise the fullness of the valve lift diagram, the time-area of the whole opening, or the "
                   "breathing's volumetric efficiency or torque (fired), the mean over the conditions and curve speeds "
                   "of the file's [breathing] section.")
@click.option("--vary", "vary", multiple=True, metavar="KEY=LOW,HIGH",
              help="A numeric key under [valves.NAME] and its bounds (repeatable), e.g. cam.phi1_deg=20,35 or "
                   "drive.spring_reserve=1.5,2.25; default: the law's own variables.")
@click.option("--no-jump", "no_jump", default=None, type=_Range(0.0, 3.0),
              help="No follower separation up to this multiple of the rated speed (one-mass train of the valve's "
                   "[dynamics] section or its estimates); 0 leaves the dynamics out. Default: [engine] "
                   "over_speed_ratio (1.1 unless given).")
@click.option("--cam-width", "cam_width", default=None, type=_Range(1.0, 200.0), metavar="MM",
              help="Cam width [mm] of the Hertz contact stress; default: the valve's parts.cam_width_mm, else half "
                   "the base radius (a narrow cam, so the stress is not understated).")
@click.option("--seating-velocity", "seating_velocity", default=None, type=_Range(0.01, 10.0),
              metavar="M_S", help="Largest valve seating velocity [m/s] (kinematic in the search, the dynamics "
                                  "sweep's too at the end); default: no such limit.")
@click.option("--wheel-radius", "wheel_radius", default=None, type=_Range(5.0, 1000.0),
              metavar="MM", help="Grinding wheel radius [mm] that a roller follower cam's concave stretches must "
                                 "take; default: the valve's [grinding] section's, else no such limit.")
@click.option("--seed", default=1, show_default=True, type=click.IntRange(0, 2 ** 32 - 1),
              help="Seed of the differential evolution.")
@click.option("--maxiter", default=60, show_default=True, type=click.IntRange(1, 10000),
              help="Generations of the differential evolution.")
@click.option("--lang", type=click.Choice(["en", "ru"]), default="en", show_default=True,
              help="Language of the report and the plot.")
@click.option("--force", is_flag=True, help=FORCE_HELP)
def optimize(file, out, valve, objective, vary, no_jump, cam_width, seating_velocity, wheel_radius, seed, maxiter,
             lang, force) -> None:
    """Maximise the fullness, time-area or breathing of a valve's cam of FILE under its limits and write the optimum
    to --out.

    Varies the law's parameters (Kurz: phi1, phi2, Z; constant acceleration: phi1, phi2, kappa; polydyne: the
    exponents; combined: the ratios; each with the ramp end velocity and the spring reserve K_z; the power
    polynomial: a_qd, phi_1, x_d, x_g) or the keys of --vary, with a differential evolution and a local polish,
    under the design's own limits: the spring reserve, the tappet acceleration band (kept at the start's value
    where the start is outside it), the smallest convex contour radius (2 mm) and the Hertz stress (1200 MPa, from
    standstill to the over-speed), the pressure angle (30 deg) and the grinding wheel of a roller follower, the ramp
    end velocity band, the seating velocity with --seating-velocity, and no jump up to --no-jump x the rated speed
    (UkrSURT Proceedings (2019); Shang Hanji (1988), section 4.3 and chapter 3). The optimum is the best point
    evaluated whose full design meets every limit, the start included. A breathing objective (a file with
    [breathing], the valve's side lifted by the designed valves) converges the breathing's cycles at each of its
    speeds per point, with no local polish, and its cycles must repeat at the optimum. Writes optimum.toml (a specification that
    valvetrain run accepts), optimization.json, comparison.csv, history.csv, history.png and report.html; where no
    point meets every limit, writes nothing, names the limits that fail and exits 1."""
    from .export import json_text, write_csv
    from .outfolder import atomic_folder
    from .report.optimization import (HISTORY_COMMENTS, comparison_columns, history_columns, history_figure,
                                      report_html)
    from .synthesis.objectives import shown_objective
    from .synthesis.optimize import optimize_valve
    from .synthesis.variables import parse_variables
    from .units import MM

    spec = _load(file)
    inputs = _check_out(out, [file], [spec], force)
    try:
        variables = parse_variables(vary) if vary else None
    except ValueError as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    no_jump = spec.engine.over_speed_ratio if no_jump is None else no_jump
    progress = _Progress("generations")
    progress("optimize", 0, maxiter)
    try:
        result = optimize_valve(spec, valve, variables, objective,
                                None if wheel_radius is None else wheel_radius * MM, no_jump or None,
                                seed=seed, maxiter=maxiter,
                                progress=lambda generation, best: progress("optimize", generation, maxiter),
                                cam_width=None if cam_width is None else cam_width * MM,
                                seating_velocity=seating_velocity)
    except SpecError as err:
        _fail_spec(err)
    except ValueError as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    finally:
        progress.close()
    if not result.feasible:
        click.echo(f"error: no point of the search meets every limit ({result.evaluations} evaluations, start "
                   "included); nothing written. The limits that fail:", err=True)
        for where, checks in (("at the point nearest to them", result.checks), ("at the start", result.checks_start)):
            for c in checks:
                if not c.passed:
                    note = f" [{c.note}]" if c.note else ""
                    click.echo(f"  {where}: {c.statement}{note}, allowed {c.range}", err=True)
        sys.exit(1)
    record = {"valve": result.valve, "objective": result.objective, "start": result.start, "optimum": result.optimum,
              "bounds": dict(zip(result.start, result.bounds, strict=True)),
              "start_value": result.start_value, "value": result.value, "feasible": result.feasible,
              "binding": [c.quantity for c in result.binding], "fast_margins": result.margins,
              "limit_notes": result.limit_notes, "evaluations": result.evaluations, "seconds": result.seconds,
              "seconds_in_evaluations": result.seconds_in_evaluations, "law_samples": result.law_samples,
              "simulations": result.simulations,
              "comparison": [dict(zip(("quantity", "unit", "start", "optimum"), r, strict=True))
                             for r in result.comparison],
              "constraints_start": [c.as_dict() for c in result.checks_start],
              "constraints": [c.as_dict() for c in result.checks]}
    if result.polydyne_fullness is not None:
        record["polydyne_2_10_18_26_34_tappet_fullness"] = result.polydyne_fullness
    try:
        with atomic_folder(out, inputs, force) as tmp:
            (tmp / "optimum.toml").write_text(result.spec_text, encoding="utf-8")
            (tmp / "optimization.json").write_text(json_text(record) + "\n", encoding="utf-8")
            write_csv(tmp / "comparison.csv", comparison_columns(result))
            write_csv(tmp / "history.csv", history_columns(result), HISTORY_COMMENTS)
            history_figure(result, lang).savefig(tmp / "history.png", dpi=110)
            (tmp / "report.html").write_text(report_html(result, lang), encoding="utf-8")
    except OutFolderError as err:
        _fail_out(err)
    click.echo(f"{result.valve}: {objective} {shown_objective(objective, result.start_value):.6g} -> "
               f"{shown_objective(objective, result.value):.6g} "
               f"({result.evaluations} evaluations, {result.seconds:.1f} s)"
               + (f"; the polydyne (2, 10, 18, 26, 34) of the same lift, ramp and angle: tappet fullness "
                  f"{result.polydyne_fullness:.4f}" if result.polydyne_fullness is not None else ""))
    if result.optimum == result.start:
        click.echo("  no point better than the start meets every limit: the optimum is the start")
    for key, value in result.optimum.items():
        click.echo(f"  {key} = {value:.6g}")
    for c in result.checks:
        state = "binds" if c in result.binding else "ok"
        note = f" [{c.note}]" if c.note else ""
        click.echo(f"  {c.quantity}{note} {'= ' if c.evaluated else ''}{c.value_text} ({c.range}), margin "
                   f"{c.margin:.4f} {state}")
    click.echo(f"wrote {out}/ (optimum.toml, optimization.json, comparison.csv, history.csv, history.png, report.html)")


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--grid", "grid_items", multiple=True, required=True, metavar="KEY=V1,V2,...",
              help="A dotted key of FILE and its values (repeatable): valves.intake.cam.shape_factor=0.5,0.6,0.7; "
                   "the points are the cartesian product of the grids.")
@click.option("--out", "out", default="study", show_default=True, type=click.Path(), help=OUT_HELP)
@click.option("--workers", default=1, show_default=True, type=click.IntRange(1, 1024),
              help="Local processes evaluating the points.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Evaluate the points on the Dask distributed cluster of this scheduler (tcp://host:8786); "
                   "needs pip install 'valvetrain[dask]'.")
@click.option("--max-points", "max_points", default=None, type=click.IntRange(1), metavar="N",
              help="Allow a grid of up to N points, however long it takes (default: a grid whose estimated time, "
                   "from a timed design of FILE, is over an hour is refused with the estimate).")
@click.option("--force", is_flag=True, help=FORCE_HELP)
def study(file, grid_items, out, workers, scheduler, max_points, force) -> None:
    """Design every point of a grid of FILE's keys and write one table of results to --out.

    Each point is FILE with the grid's values, validated and designed like `valvetrain run`; a point that is
    refused is a row with its messages. Per point and valve: time-area, fullness, max/min tappet acceleration,
    rho_min, max contact stress, the spring (wire, preload, whether it passes), the jump speed of a valve with a
    [dynamics] section; per point the counts of failures and warnings. Writes study.csv and study.json; a study
    stopped by a worker process that died writes the points designed before it and exits 1."""
    from .export import json_text, write_csv
    from .outfolder import atomic_folder
    from .study import (POINT_COLUMNS, VALVE_COLUMNS, GridError, StudyStopped, check_grid,
                        count_points, evaluate, parse_grid, point_text, points, read_document, table, too_large,
                        with_values)

    _load(file)
    if scheduler is not None and workers > 1:
        click.echo("error: --workers and --scheduler: give one (the cluster's workers evaluate the points)", err=True)
        sys.exit(2)
    inputs = _check_out(out, [file], [], force)
    try:
        grid = parse_grid(grid_items)
        document = read_document(file)
        check_grid(document, grid)                        # before the timed design of too_large's estimate
        total = count_points(grid)
        large = too_large(total, max_points, document, workers if scheduler is None else 1, "design points",
                          "--max-points")
        if large:
            raise GridError(f"--grid: {large}")
    except GridError as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    progress = _Progress("design points")
    start = time.monotonic()
    stopped = None
    try:
        records = evaluate((with_values(document, p) for p in points(grid)), total, workers, scheduler,
                           lambda done, total: progress("study", done, total),
                           lambda i: point_text(next(itertools.islice(points(grid), i, None))))
    except (ImportError, ConnectionError) as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    except StudyStopped as err:
        stopped, records = err, err.records
    finally:
        progress.close()
    seconds = time.monotonic() - start
    columns = table(grid, records)
    meanings = dict(VALVE_COLUMNS) | dict(POINT_COLUMNS)
    try:
        with atomic_folder(out, inputs, force) as tmp:
            write_csv(tmp / "study.csv", columns)
            (tmp / "study.json").write_text(json_text({
                "file": file, "grid": dict(grid),
                "columns": {c: "grid value" if c in dict(grid) else meanings[c.rpartition(".")[2]] for c in columns},
                "points": [dict(zip(columns, row, strict=True)) for row in zip(*columns.values(), strict=True)],
            }) + "\n", encoding="utf-8")
    except OutFolderError as err:
        _fail_out(err)
    done = [r for r in records if r is not None]
    refused = sum(r["status"] == "refused" for r in done)
    failed = [r["message"] for r in done if r["status"] == "failed"]
    backend = f"on {scheduler}" if scheduler else f"in {workers} processes" if workers > 1 else "in this process"
    click.echo(f"{len(done)} design points ({refused} refused"
               + (f", {len(failed)} failed with an error of valvetrain: {failed[0]}" if failed else "")
               + f") {backend}, {seconds:.1f} s")
    click.echo(f"wrote {out}/ (study.csv, study.json)")
    if stopped is not None:
        click.echo(f"error: {stopped}; the rows of the points not designed say 'not designed'", err=True)
        sys.exit(1)


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--samples", required=True, type=click.IntRange(2, 10_000_000),
              help="Number of samples; with --method sobol the base points N of Saltelli's scheme, a power of two "
                   "(2, 4, 8, ...): N (D + 2) samples are designed for D tolerances.")
@click.option("--method", type=click.Choice(["mc", "lhs", "sobol"]), default="mc", show_default=True,
              help="Monte Carlo (mc), Latin hypercube (lhs), or Saltelli's scheme on a Sobol' sequence (sobol: "
                   "also the first-order and total Sobol' indices of every margin and dynamics headline).")
@click.option("--seed", default=0, show_default=True, type=click.IntRange(0), help="Seed of the samples.")
@click.option("--out", "out", default="tolerance", show_default=True, type=click.Path(file_okay=False),
              help="Folder of the study: new or empty, or the folder of an interrupted run of the same study, "
                   "which is continued.")
@click.option("--workers", default=1, show_default=True, type=click.IntRange(1, 1024),
              help="Local processes evaluating the samples.")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Evaluate the samples on the Dask distributed cluster of this scheduler (tcp://host:8786); "
                   "needs pip install 'valvetrain[dask]'.")
@click.option("--max-samples", "max_samples", default=None, type=click.IntRange(1), metavar="N",
              help="Allow up to N samples designed (with --method sobol N (D + 2) for --samples N), however long "
                   "they take (default: samples whose estimated time, from a timed design of FILE, is over an hour "
                   "are refused with the estimate).")
@click.option("--lang", type=click.Choice(["en", "ru"]), default="en", show_default=True,
              help="Language of the report.")
@click.option("--force", is_flag=True,
              help="Write into --out even if it holds files that valvetrain tolerance did not write: they are left "
                   "as they are.")
def tolerance(file, samples, method, seed, out, workers, scheduler, max_samples, lang, force) -> None:
    """Sample FILE's [[tolerances]] and design every sample; per check the distribution of its margin, its
    probability of failure and the tolerances that drive it.

    The samples are the same for the same FILE, --samples, --method and --seed, whatever --workers or --scheduler.
    The records are written to --out/records.jsonl as they arrive: run the same command again after an
    interruption and only the samples missing are designed. Writes tolerance.json and the report tolerance.html
    (tables and histograms) when every sample is designed; with --method sobol also the first-order and total Sobol'
    indices of every check's margin and dynamics headline with their 95 % intervals."""
    from .export import json_text
    from .report.tolerance import report_html
    from .study import StudyStopped, evaluate, read_document, too_large, with_values
    from .tolerance import (RECORDS, RecordFile, ToleranceError, check_tolerances, draw, evaluate_sample,
                            fingerprint, fresh_sample, sample_count, summary)

    spec = _load(file)
    if scheduler is not None and workers > 1:
        click.echo("error: --workers and --scheduler: give one (the cluster's workers evaluate the samples)", err=True)
        sys.exit(2)
    try:
        folder = out_path(out)
    except OutFolderError as err:
        _fail_out(err)
    ours = {"records.tmp", *(f"tolerance.{x}{t}" for x in ("json", "html") for t in ("", ".tmp"))}
    if folder.exists() and (not folder.is_dir() or any(p.name in ours and not p.is_file() or not force
                                                       and p.name not in ours | {RECORDS} for p in folder.iterdir())):
        _fail_out(OutFolderError(f"{out}: holds files that valvetrain tolerance did not write; give a new or empty "
                                 "folder, or --force to write beside them"))
    if not folder.exists() and (problem := location_problem(folder.resolve())):
        _fail_out(OutFolderError(f"{out}: {problem}"))
    try:
        document = read_document(file)
        centres = check_tolerances(document, spec)
        total = sample_count(samples, len(centres), method)
        large = too_large(total, max_samples, document, workers if scheduler is None else 1, "samples",
                          "--max-samples", fresh_sample)
        if large:
            raise ToleranceError(f"--samples: {large}")
        values = draw(spec, centres, samples, method, seed)
        records_file = RecordFile(folder, fingerprint(document, method, seed, values))
        done = records_file.read(total)
    except ToleranceError as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    for number, why in records_file.damaged[:5]:
        click.echo(f"note: {folder / RECORDS} line {number}: {why}; its sample is designed again", err=True)
    if len(records_file.damaged) > 5:
        click.echo(f"note: {len(records_file.damaged) - 5} more lines of {RECORDS} designed again", err=True)
    keys = [t.key for t in spec.tolerances]
    todo = [i for i in range(total) if i not in done]
    progress = _Progress("samples")
    start = time.monotonic()
    records_file.open(done)
    try:
        records = evaluate((with_values(document, dict(zip(keys, map(float, values[i]), strict=True))) for i in todo),
                           len(todo), workers, scheduler, lambda d, total: progress("tolerance", d, total),
                           lambda j: f"sample {todo[j]}", evaluate_sample,
                           lambda j, record: records_file.keep(todo[j], record))
    except (ImportError, ConnectionError) as err:
        click.echo(f"error: {err}", err=True)
        sys.exit(2)
    except StudyStopped as err:
        click.echo(f"error: {err}; run the same command again to continue", err=True)
        sys.exit(1)
    finally:
        progress.close()
        records_file.close()
    done.update(zip(todo, records, strict=True))
    result = summary(spec, centres, values, [done[i] for i in range(total)], method, seed)
    for name, text in (("tolerance.json", json_text({"file": file, **result}) + "\n"),
                       ("tolerance.html", report_html(result, lang))):
        tmp = folder / f"{name}.tmp"
        tmp.write_text(text, encoding="utf-8")
        tmp.replace(folder / name)
    backend = f"on {scheduler}" if scheduler else f"in {workers} processes" if workers > 1 else "in this process"
    failed = result["failed"]["samples"]
    click.echo(f"{len(todo)} samples designed ({total - len(todo)} kept from before) {backend}, "
               f"{time.monotonic() - start:.1f} s; {result['refused']['samples']} refused"
               + (f" ({failed} of them failed with an error of valvetrain: {result['failed']['messages'][0]})"
                  if failed else ""))
    failing = sorted(((c["accepted"], -c["probability"], cid) for cid, c in result["checks"].items() if c["failures"]))
    for accepted, p, cid in failing:
        low, high = result["checks"][cid]["confidence_95"]
        click.echo(f"  {'accepted in the specification: ' if accepted else ''}{result['checks'][cid]['quantity']}: "
                   f"P(fail) = {-p:.4g} (95 %: {low:.4g}...{high:.4g})")
    click.echo(f"wrote {out}/ ({RECORDS}, tolerance.json, tolerance.html)")


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--strict", is_flag=True, help=STRICT_HELP)
def validate(file, strict) -> None:
    """Check a specification FILE; exit status 2 and one message per problem if it is not valid.

    The design is computed (nothing is written), so a file that validates also runs, and its
    failed checks are printed as `run` prints them: ranked, failures first, those accepted in
    the file's [[accepted]] tables left out.  Exit status 0 whatever the checks say (failures
    are results of the design, not errors of the input); 2 also for an [[accepted]] table that
    names no check; with --strict, 1 when a failure is open."""
    spec = _load(file)
    results = _design(spec)
    click.echo(f"{file}: valid ({len(spec.valves)} valve(s): {', '.join(spec.valves)})")
    _strict_exit(_echo_checks(results), strict)


@main.command()
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option("--out", "out", default="compare", show_default=True, type=click.Path(), help=OUT_HELP)
@click.option("--force", is_flag=True, help=FORCE_HELP)
def compare(files, out, force) -> None:
    """Compare the cams of every valve of FILES side by side (time-area, fullness, kinematics, curvature,
    contact stress, required spring) and their trains' dynamics (drive load, spring, reduced mass, drive stiffness,
    natural frequency, resonant harmonic, distortion, and the jump speed of a 40-speed one-mass sweep over each
    valve's [dynamics] range), and the breathing of the files with a [breathing] section (air flow, volumetric
    efficiency, IMEP, peak pressure, torque at each condition); writes compare.csv, compare_breathing.csv,
    compare.json and overlaid plots."""
    from .compare import table_cell, shown_metrics, with_dynamics, write_comparison

    specs = [_load(f) for f in files]
    if not any(spec.valves or spec.breathing is not None for spec in specs):
        click.echo("error: the files define no valves and no [breathing] to compare", err=True)
        sys.exit(2)
    inputs = _check_out(out, files, specs, force)
    designs, breathing = {}, {}
    for spec, label in zip(specs, _file_labels(files), strict=True):
        results = _design(with_dynamics(spec))
        for name, v in results.valves.items():
            designs[f"{label}:{name}" if len(files) > 1 else name] = v
        if results.breathing is not None:
            breathing[label] = results.breathing
    try:
        rows, notes = write_comparison(designs, out, inputs, force, breathing)
    except OutFolderError as err:
        _fail_out(err)
    if rows:
        metrics = shown_metrics(rows)
        width = max(len(label) for _, label in metrics)
        click.echo(" " * width + "".join(f"  {lab[:18]:>18}" for lab in rows))
        for key, label in metrics:
            cells = "".join(f"  {cell:>18}" if isinstance(cell, str) else f"  {cell:>18.6g}"
                            for cell in (table_cell(r.get(key)) for r in rows.values()))
            click.echo(f"{label:<{width}}{cells}")
    for label, b in breathing.items():
        for part in ("conditions", "curve"):
            for r in b.summary[part]:
                click.echo(f"{label} breathing: {r['speed_rpm']:.5g} rpm, {r['intake_pressure_kPa']:.5g} kPa: air "
                           f"{r['air_mass_flow_g_s']:.4g} g/s, volumetric efficiency {r['volumetric_efficiency']:.4g}, "
                           f"IMEP {r['imep_kPa']:.4g} kPa")
    for n in notes:
        click.echo(f"note: {n}")
    written = ["compare.csv"] * bool(rows) + ["compare_breathing.csv"] * bool(breathing)
    click.echo(f"wrote {out}/ ({', '.join(written + ['compare.json', 'plots/'])})")


def _file_labels(files):
    """Short distinct labels of files: the name without suffix, with as many parent folders as tell them apart
    (``v1/engine`` and ``v2/engine``); the same file given twice is counted (``engine (2)``)."""
    from pathlib import Path

    parts = [Path(f).with_suffix("").parts for f in files]
    depth = 1
    while len({p[-depth:] for p in parts}) < len(set(parts)):
        depth += 1
    labels = ["/".join(p[-depth:]) for p in parts]
    return [lab if labels.count(lab) == 1 else f"{lab} ({labels[:i + 1].count(lab)})" for i, lab in enumerate(labels)]


@main.command()
def schema() -> None:
    """Print the JSON Schema of results.json (generated from the design's result types)."""
    from .design import results_schema
    from .export import json_text

    click.echo(json_text(results_schema()))


@main.command()
@click.argument("file", required=False, type=click.Path(dir_okay=False))
@click.option("--port", default=5006, show_default=True, type=click.IntRange(0, 65535),
              help="Port of the designer (0: any free port).")
@click.option("--host", default="127.0.0.1", show_default=True,
              help="Address to listen on; anything but 127.0.0.1 exposes the designer to the network.")
@click.option("--show/--no-show", default=True, help="Open the page in the browser.")
def serve(file, port, host, show) -> None:
    """The designer in the browser: edit FILE (default: the built-in example), drag the cam's handles and watch the
    checks and the speed sweep answer.  Needs the extra `pip install "valvetrain[web]"`; works offline; writes
    nothing but what you download.  Ctrl-C stops it."""
    from pathlib import Path

    try:
        from .web import server
    except ImportError as exc:
        click.echo(f"error: the designer needs the web extra: pip install \"valvetrain[web]\" ({exc})", err=True)
        sys.exit(2)
    text, folder = None, None
    if file:
        _load(file)
        text, folder = Path(file).read_text(encoding="utf-8"), Path(file).resolve().parent
    if host != "127.0.0.1":
        click.echo(f"warning: --host {host}: the designer is open to every machine that reaches this address; it "
                   "has no login", err=True)
    try:
        app = server(text, folder, host, port)
    except SpecError as err:
        _fail_spec(err)
    except OSError as err:   # the port taken, an address not of this machine, a name that does not resolve
        click.echo(f"error: --host {host} --port {port}: cannot listen there ({err.strerror or err}); give another "
                   "--port (0: any free port) or --host", err=True)
        sys.exit(2)
    app.start()
    url = f"http://{'127.0.0.1' if host in ('127.0.0.1', '0.0.0.0') else host}:{app.port}/"
    click.echo(f"valvetrain designer at {url} (Ctrl-C stops it)")
    if show:
        app.io_loop.add_callback(app.show, "/")
    app.io_loop.start()


@main.command()
def example() -> None:
    """Print the built-in example specification (the appendix of Valve-train practical works (n.d.) engine) as TOML."""
    click.echo(example_text(), nl=False)


def program() -> None:
    """The ``valvetrain`` program: :func:`main`, then Ctrl-C ignored while Python shuts down.

    The command is done by then (its exit status is set); Python's shutdown restores the
    default SIGINT action, which would kill the process with no message instead.
    """
    try:
        main()
    finally:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
