"""The figures of a run drawn in other processes, which import matplotlib while the first one designs.

Drawing is most of what ``valvetrain run`` costs after the design (importing matplotlib, a third of a second, then
about 0.1-0.4 s a figure), and it needs nothing but the results: a process forked before the design imports
matplotlib meanwhile and draws one figure (its fonts loaded, the PNG writer imported), forks :data:`PROCESSES` - 1
more from itself (which find matplotlib imported), then imports the modules of the other files it is to write
(:class:`FigureProcess`'s ``imports``: the DXF writer).  The drawers evaluate no lift law for the main figures (the
timing diagram's lifts are evaluated in the first process, :func:`figure_inputs`), so that the first process forks
them before it loads numba's compiled code (the first call of any kernel loads it for all, 0.2-0.5 s), which it does
while they import matplotlib; a figure of ``--figures all`` that evaluates a law (the curvature) loads it in its
drawer.  Each drawer receives the results once they are there (what the figures asked for
read, :func:`figure_inputs`) from its own pipe; the first sends back the files of the figures (which the report
names), writes the other files it was given (``submit``'s ``also``: the DXF files of the contours), and they draw
the figures while the first process writes the tables and renders the report, which embeds them once drawn.  The
drawers share the figures through a counter: each takes the next figure not yet taken
(:func:`valvetrain.report.plots.write_plots`'s ``claim``), so that one drawing an expensive figure does not hold
back the others.  Where processes cannot be forked (Windows, macOS), :func:`start` gives None and the figures are
drawn in the process itself, as before.
"""

from dataclasses import replace
import gc
import importlib
import io
import itertools
import mmap
import multiprocessing
from multiprocessing.reduction import recv_handle, send_handle
import os
import pickle
import signal
import sys
import threading

from ..design import DesignResults
from ..errors import ValvetrainError


class DrawingError(ValvetrainError, RuntimeError):
    """A process drawing the figures that ended without them, or an error of its drawing that could not be sent."""


PROCESSES = 2
"""Drawing processes: the figures and the first process's writing share two cores (this machine's, and a laptop's
least); more would only wait for a core."""


class FigureProcess:
    """A forked process that draws the figures of one run, with those it forks (:func:`_serve`).

    :meth:`submit` sends it the results and the folder, :meth:`result` waits for the files written (and raises what a
    drawing process raised).  As a context manager it ends the processes on leaving (:meth:`stop`), so that nothing
    is written into a folder the caller removes after an error.
    """

    def __init__(self, processes=PROCESSES, imports=()):
        context = multiprocessing.get_context("fork")
        pipes = [context.Pipe() for _ in range(processes)]     # one a drawer: its request (the first's: its answer)
        self._conns = [mine for mine, _ in pipes]
        self._process = context.Process(target=_serve, args=([child for _, child in pipes], self._conns, imports),
                                        daemon=True)
        self._process.start()
        for _, child in pipes:
            child.close()
        self._conn = self._conns[0]
        self._sending = self._names = None

    def submit(self, results, folder, lang, figures, also=None) -> None:
        """Draw the figures ``figures`` of ``results`` into ``folder`` (the arguments of ``write_plots``); first
        call ``also()`` in the first drawer, if given (a picklable callable that writes other files of the results,
        with the modules of ``imports``).

        The request is pickled here (the results are not to be read while this process goes on with them), its
        arrays apart (pickle's protocol 5: out-of-band buffers, 70 MB of a sweep's recorded revolutions for two
        valves where the dynamics maps are drawn), copied once into a shared memory file that the drawers map
        (:func:`_shared`, :func:`_receive`) rather than pickled into the pipe, read from it and unpickled again (a
        fifth of a second of a run); the rest, larger than a pipe holds, is sent to each drawer by a thread with the
        file: this process writes its files meanwhile, rather than wait for the drawers to finish importing
        matplotlib."""
        buffers = []
        request = pickle.dumps(((results, folder, lang, figures), also), 5, buffer_callback=buffers.append)
        arrays, sizes = _shared([b.raw() for b in buffers])
        self._sending = threading.Thread(target=self._send, args=(request, sizes, arrays), daemon=True)
        self._sending.start()

    def _send(self, request, sizes, arrays):
        try:
            for conn in self._conns:
                conn.send_bytes(request)
                conn.send(sizes)
                send_handle(conn, arrays, self._process.pid)
        except OSError:      # the drawers have ended (stop): result() says so
            pass
        finally:
            os.close(arrays)

    def names(self) -> dict:
        """``write_plots``'s return value (the files of the figures, which the report names) as soon as the first
        drawer has the request, before the figures are drawn; its exception (figures not known), raised here."""
        if self._names is None:
            self._names = self._answer()
        return self._names

    def result(self) -> dict:
        """``write_plots``'s return value, once every process has drawn its figures; an exception of one, raised
        here."""
        self.names()
        value = self._answer()
        self._process.join()
        return value

    def _answer(self):
        try:
            ok, value = self._conn.recv()
        except EOFError:
            raise DrawingError("a process drawing the figures ended without them") from None
        if not ok:
            raise value
        return value

    def stop(self) -> None:
        """End the processes (at once, where one still draws: the first ends those it forked) and close the pipe."""
        if self._process.is_alive():
            self._process.terminate()
        self._process.join()
        if self._sending is not None:
            self._sending.join()
        for conn in self._conns:
            conn.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()


def start(imports=()) -> FigureProcess | None:
    """A :class:`FigureProcess` that imports ``imports`` too, or None where processes are not forked (only Linux
    forks safely here)."""
    return FigureProcess(imports=imports) if sys.platform.startswith("linux") else None


def figure_inputs(results, figures) -> DesignResults:
    """``results`` as the figures of ``figures`` (``write_plots``'s) read them: without the recorded revolutions of
    the speed sweeps (``dynamics.sweep``) but where ``figures`` is ``"all"``, the only set that draws the dynamics
    maps, which alone show them (not in :data:`valvetrain.report.plots.MAIN_FIGURES`).  Those are most of what
    :meth:`FigureProcess.submit` would copy to the drawers (the built-in example's two valves: 70 MB of arrays and
    12 MB pickled), and copied in vain.  Each valve's lift over the cycle (the timing diagram's,
    :attr:`valvetrain.design.valve.ValveDesign.cycle_lift`) is evaluated here, where the laws' compiled code is
    loaded: a drawer would load it to evaluate a law (0.2 s)."""
    if figures != "all":
        results = replace(results, valves={name: v if v.dynamics is None or v.dynamics.sweep is None else
                                           replace(v, dynamics=replace(v.dynamics, sweep=None))
                                           for name, v in results.valves.items()})
    for v in results.valves.values():
        v.cycle_lift   # noqa: B018 - evaluated and kept (a cached property)
    return results


def _serve(conns, others, imports):
    """The forked process: import the plots and draw one figure, fork the other drawers (one a pipe of ``conns``
    after the first, this one's), import ``imports``, wait for the request, write its other files, draw the figures
    it claims, send back the files or the first error; where the first process has ended (killed), end quietly.

    The drawers are forked before the request comes, each to read it from its own pipe: none waits for this one to
    finish importing ``imports`` (the DXF writer, a fifth of a second) when the request comes meanwhile.  A Ctrl-C is
    the first process's to handle (it ends this one); the ends of the pipes that process keeps (``others``) are closed
    here, so that the process ending without a request is an end of file, not a wait for ever.  Ended (SIGTERM,
    :meth:`FigureProcess.stop`), it kills the drawers it forked first (SIGKILL: a SIGTERM can be lost in a drawer
    just forked, which still holds this handler when the signal comes and has reset it when Python would run it, so
    that this process waited for it for ever and the run with it)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for other in others:
        other.close()
    conn = conns[0]
    try:
        _warm_up()           # matplotlib imported, its fonts loaded, while the first process designs
    except ImportError:
        pass                 # raised again with the request, in the first process
    drawers = []
    taken = multiprocessing.Value("i", 0, lock=True)   # the number of the next figure no drawer has taken

    def claim():
        with taken.get_lock():
            taken.value += 1
            return taken.value - 1

    def end(*_):
        for pid, _conn in drawers:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
        os._exit(1)

    signal.signal(signal.SIGTERM, end)
    for own in conns[1:]:
        mine, theirs = multiprocessing.Pipe(duplex=False)
        pid = os.fork()
        if pid == 0:                                  # a drawer: its request, its share, its answer, its end
            try:
                signal.signal(signal.SIGTERM, signal.SIG_DFL)
                for c in conns:
                    if c is not own:
                        c.close()
                mine.close()
                try:
                    request, _ = _receive(own)
                except EOFError:
                    return
                gc.freeze()                           # nor through the request (as _warm_up)
                _send(theirs, _draw(request, claim))
            finally:
                os._exit(0)
        own.close()
        theirs.close()
        drawers.append((pid, mine))
    try:
        if not conn.poll():  # the other modules while the request is not there yet (else: where they are used)
            for name in imports:
                importlib.import_module(name)
    except ImportError:
        pass                 # raised again with the request, in the first process
    try:
        request, also = _receive(conn)
    except EOFError:
        end()
    gc.freeze()              # nor through the request and the modules of ``imports`` (as _warm_up)
    if not _send(conn, _draw(request, lambda: -1)):  # the names alone (a claim of no figure): the report's
        end()                # the first process has ended: no figure is wanted
    answers = [_draw(request, claim, also)]
    for pid, mine in drawers:
        try:
            answers.append(mine.recv())
        except EOFError:
            answers.append((False, DrawingError("a process drawing the figures ended without them")))
        os.waitpid(pid, 0)
    _send(conn, next((a for a in answers if not a[0]), answers[0]))


def _shared(buffers) -> tuple[int, list[int]]:
    """A shared memory file (its descriptor, Linux's ``memfd_create``) holding ``buffers`` (byte views) one after
    the other, and their sizes [bytes]."""
    fd = os.memfd_create("valvetrain-figures")
    for b in buffers:
        while b.nbytes:
            b = b[os.write(fd, b):]
    return fd, [b.nbytes for b in buffers]


def _receive(conn):
    """The request of :meth:`FigureProcess.submit`, unpickled with its arrays in the shared memory file it sends
    (mapped here, its pages at once: the drawers read the arrays where the first process wrote them)."""
    request, sizes, fd = conn.recv_bytes(), conn.recv(), recv_handle(conn)
    try:
        memory = memoryview(mmap.mmap(fd, sum(sizes), flags=mmap.MAP_SHARED | mmap.MAP_POPULATE) if sum(sizes)
                            else b"")
    finally:
        os.close(fd)
    buffers = [memory[start:start + size] for start, size in zip(itertools.accumulate(sizes, initial=0), sizes)]
    return pickle.loads(request, buffers=buffers)


def _send(conn, answer) -> bool:
    """Send an answer of :func:`_draw`; an exception that cannot be pickled as a DrawingError that names it.  False
    where no one reads it any more (the first process ended, killed even: a SIGKILL runs no cleanup), True else."""
    try:
        try:
            conn.send(answer)
        except (BrokenPipeError, ConnectionResetError):
            raise
        except Exception:  # noqa: BLE001 - an exception that cannot be pickled
            conn.send((False, DrawingError(f"drawing the figures: {answer[1]!r}")))
    except (BrokenPipeError, ConnectionResetError):
        return False
    return True


def _draw(request, claim, also=None):
    """``(True, write_plots's files)`` of the figures that this drawer claims (``claim``; one that gives -1 claims
    none), after ``also()`` if given, or ``(False, the exception)``."""
    try:
        from .plots import write_plots

        if also is not None:
            also()
        return True, write_plots(*request, claim=claim)
    except Exception as exc:  # noqa: BLE001 - raised again in the first process (FigureProcess.result)
        return False, exc


def _warm_up():
    """Import matplotlib and draw a small figure with text into memory: what the first figure of a process costs
    beyond the others (fonts found and loaded, the PNG writer imported) is paid once, before the drawers fork.

    The garbage collector's objects are frozen before and after (``gc.freeze``): a full collection in a drawer no
    longer looks through the objects of the first process nor those of matplotlib's modules (one took 0.1 s of
    processor time in each drawer and one during the import, in a run of the built-in example)."""
    gc.freeze()
    try:
        from . import plots

        fig = plots.Figure(figsize=(1, 1))
        ax = fig.subplots()
        ax.plot([0.0, 1.0], label="0")
        ax.legend()
        ax.set_title("0")
        plots.write_png(fig, io.BytesIO())
    finally:
        gc.freeze()
