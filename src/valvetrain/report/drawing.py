"""The figures of a run drawn in other processes, which import matplotlib while the first one designs.

Drawing is most of what ``valvetrain run`` costs after the design (importing matplotlib, a third of a second, then
about 0.1-0.2 s a figure), and it needs nothing but the results: :data:`PROCESSES` processes forked before the design
import matplotlib meanwhile, receive the results once they are there, and draw the figures dealt round between them
(:func:`valvetrain.report.plots.write_plots`'s ``share``) while the first process writes the tables, the contours
and the DXF files.  Where processes cannot be forked (Windows, macOS), :func:`start` gives None and the figures are
drawn in the process itself, as before.
"""

import multiprocessing
import signal
import sys

PROCESSES = 2
"""Drawing processes: the figures and the first process's writing share two cores (this machine's, and a laptop's
least); more would only wait for a core."""


class FigureProcess:
    """Forked processes that draw the figures of one run between them (:func:`valvetrain.report.plots.write_plots`).

    :meth:`submit` sends them the results and the folder, :meth:`result` waits for the files they wrote (and raises
    what one raised).  As a context manager it ends the processes on leaving, so that nothing is written into a
    folder the caller removes after an error.
    """

    def __init__(self, processes=PROCESSES):
        context = multiprocessing.get_context("fork")
        self._conns, self._processes = [], []
        for _ in range(processes):
            conn, child = context.Pipe()
            process = context.Process(target=_serve, args=(child, [conn, *self._conns]), daemon=True)
            process.start()
            child.close()
            self._conns.append(conn)
            self._processes.append(process)

    def submit(self, results, folder, lang, figures):
        """Draw the figures ``figures`` of ``results`` into ``folder`` (the arguments of ``write_plots``)."""
        n = len(self._conns)
        for k, conn in enumerate(self._conns):
            conn.send((results, folder, lang, figures, (k, n)))

    def result(self):
        """``write_plots``'s return value, once every process has drawn its figures; an exception of one, raised
        here."""
        answers = []
        for conn, process in zip(self._conns, self._processes, strict=True):
            try:
                answers.append(conn.recv())
            except EOFError:
                raise RuntimeError("a process drawing the figures ended without them") from None
            process.join()
        for ok, value in answers:
            if not ok:
                raise value
        return answers[0][1]

    def stop(self):
        """End the processes (at once, where one still draws) and close the pipes."""
        for process in self._processes:
            if process.is_alive():
                process.terminate()
            process.join()
        for conn in self._conns:
            conn.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()


def start():
    """A :class:`FigureProcess`, or None where processes are not forked (only Linux forks safely here)."""
    return FigureProcess() if sys.platform.startswith("linux") else None


def _serve(conn, others):
    """A forked process: import the plots, wait for one request, draw its share, send back the files or the error.

    A Ctrl-C is the first process's to handle (it ends this one); the ends of the pipes that process keeps (``others``,
    its end of this one's and of those forked before) are closed here, so that the process ending without a request
    is an end of file, not a wait for ever."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for other in others:
        other.close()
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
