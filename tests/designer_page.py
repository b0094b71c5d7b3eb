"""The designer's page on a Bokeh document without a browser, for the tests of web/: a designer on a session, its
handlers called as the page calls them, the callbacks its worker threads leave run."""

from bokeh.document import Document

from valvetrain.web.app import Designer
from valvetrain.web.draw import _now
from valvetrain.web.form import form
from valvetrain.web.session import Session


def _row(designer, quantity, column):
    data = designer.checks.data
    return data[column][data["key"].index(quantity)]


def _field(d, path):
    return next(f for _, group in form(d.session.document, d.valve) for f in group if f.path == path)


def _request(d, kind, name="", x=0.0, y=0.0, plot="lift", text="", seq=1, finish=True):
    """What page.js sends: a handle moved, released or nudged, undo, redo, restore; a release's design (in the worker
    thread) waited for and kept unless not ``finish``."""
    d.on_request("data", {}, {"kind": [kind], "seq": [seq], "plot": [plot], "name": [name], "x": [x], "y": [y],
                              "text": [text]})
    if finish:
        d.finish_edit()


def _designer(text=None, folder=None):
    return Designer(Document(), Session.start(text, folder))


def _swept(d):
    d.draw_sweep(d.generation, Session.settle(d.session.document), _now())
    return d


def _run_callbacks(d):
    """Run the callbacks the worker threads left for the server's loop (none runs without a server), each once."""
    while d.doc.session_callbacks:
        callback = d.doc.session_callbacks[0]
        d.doc.remove_next_tick_callback(callback)
        callback.callback()
