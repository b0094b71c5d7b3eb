"""The figures of a run drawn in a second process, which imports matplotlib while the first one designs.

Drawing is most of what ``valvetrain run`` costs after the design (importing matplotlib, a third of a second, then
about 0.1-0.2 s a figure), and it needs nothing but the results: a process forked before the design imports
matplotlib meanwhile, receives the results once they are there, and draws while the first process writes the
tables, the contours and the DXF files.  Where processes cannot be forked (Windows, macOS), :func:`start` gives None
and the figures are drawn in the process itself, as before.
"""

import multiprocessing
import signal
import sys


class FigureProcess:
    """A forked process that draws the figures of one run (:func:`valvetrain.report.plots.write_plots`).

    :meth:`submit` sends it the results and the folder, :meth:`result` waits for the files it wrote (and raises what
    it raised).  As a context manager it ends the process on leaving, so that nothing is written into a folder the
    caller removes after an error.
    """

    def __init__(self):
        context = multiprocessing.get_context("fork")
        self._conn, child = context.Pipe()
        self._process = context.Process(target=_serve, args=(child, self._conn), daemon=True)
        self._process.start()
        child.close()

    def submit(self, results, folder, lang, figures):
        """Draw the figures ``figures`` of ``results`` into ``folder`` (the arguments of ``write_plots``)."""
        self._conn.send((results, folder, lang, figures))

    def result(self):
        """``write_plots``'s return value, once the process has drawn every figure; its exception, raised here."""
        try:
            ok, value = self._conn.recv()
        except EOFError:
            raise RuntimeError("the process drawing the figures ended without them") from None
        self._process.join()
        if not ok:
            raise value
        return value

    def stop(self):
        """End the process (at once, if it still draws) and close the pipe."""
        if self._process.is_alive():
            self._process.terminate()
        self._process.join()
        self._conn.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()


def start():
    """A :class:`FigureProcess`, or None where processes are not forked (only Linux forks safely here)."""
    return FigureProcess() if sys.platform.startswith("linux") else None


def _serve(conn, parent_end):
    """The forked process: import the plots, wait for one request, draw it, send back the files or the error.

    A Ctrl-C is the first process's to handle (it ends this one); the end of the pipe that process keeps is closed
    here, so that the process ending without a request is an end of file, not a wait for ever."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent_end.close()
    try:
        from . import plots  # noqa: F401 - matplotlib imported while the first process designs
    except ImportError:
        pass                 # raised again with the request, in the first process
    try:
        request = conn.recv()
    except EOFError:
        return
    try:
        from .plots import write_plots

        answer = (True, write_plots(*request))
    except Exception as exc:  # noqa: BLE001 - raised again in the first process (FigureProcess.result)
        answer = (False, exc)
    try:
        conn.send(answer)
    except Exception:  # noqa: BLE001 - an exception that cannot be pickled
        conn.send((False, RuntimeError(f"drawing the figures: {answer[1]!r}")))
