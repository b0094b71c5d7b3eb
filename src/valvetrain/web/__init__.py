"""The designer in the browser: ``valvetrain serve [FILE]`` (the optional extra ``valvetrain[web]``: Bokeh).

A Bokeh server in this process serves one page; every browser tab is a session of its own
(:class:`valvetrain.web.session.Session`) on the JSON-in/JSON-out entry point :mod:`valvetrain.api`.  The page's
scripts and styles come from the installed Bokeh package (no CDN, no web fonts): the designer works offline.
Nothing is written to disk except what the user downloads.

The page designs through :mod:`valvetrain.api` only, in steps: a drag's moves and its release answered with the
valve's kinematics alone (``api.kinematics``), then in worker threads the design without the sweeps and the springs'
diagnosis (springs, checks, breathing) and, beside it, the sweep of the valve shown, then the whole design (the shown
valve's sweep kept in ``design.run``'s memo, not swept again; a valve the edit left as it was is not designed again).  A redraw's changes go in one message, the curves thinned to what the plots show.
:mod:`.session` is one tab's state and callbacks without Bokeh, its handles read from the specification's models;
:mod:`.app` the Bokeh page, its words from the catalogue's ``[designer]``.  Bokeh is imported only there.
"""

from collections.abc import Callable
from typing import Any

LOOPBACK = "127.0.0.1"


def make_document(text, source_dir) -> Callable[[Any], None]:
    """The function that builds the page of one tab: a :class:`~valvetrain.web.app.Designer` on a new session."""
    from .app import Designer, page_key
    from .session import Session

    def build(doc):
        doc.title = "valvetrain designer"
        Designer(doc, Session.start(text, source_dir), page_key(text))

    return build


def one_message(connection, event) -> Any:
    """Bokeh's ``ServerConnection.send_patch_document`` sending the changes of a callback to the page in one message
    of three web-socket frames: each change is queued and the first of the writes that the server awaits after the
    callback sends all that are queued (the rest find the queue empty), their arrays within the message's text.

    Notes
    -----
    Bokeh sends a message per change (a redraw of the designer changes about ten models: the curves, the handles,
    the checks, the card, the stamp ...), each as four or more frames of the web socket, each waking the page; the
    page applies one message's changes in order, as it did the messages'.  The values are those the models hold
    when the message is made, after the callback: its last, as the last message would have brought.

    Bokeh sends each array of a message as two frames of its own (its reference, then its bytes): a redraw of the
    curves was 61 frames, each written and awaited in turn by the server's event loop (61 turns of the loop, each
    a wait for the interpreter's lock while the design's and the sweep's threads run) and received as a task of
    its own by the page.  Here the arrays are base64 text within the message (a third more bytes: 26 kB of curves
    become 35 kB), as Bokeh sends a standalone document's, and the message is its three frames, handed to the
    socket together (Bokeh awaits each before the next: the next tick's callbacks ran between them).
    """
    from tornado.websocket import WebSocketClosedError, WebSocketHandler

    queue = connection.__dict__.setdefault("_queued_changes", [])
    queue.append(event)

    async def send():
        if not queue:
            return
        events = list(queue)
        queue.clear()
        message, socket = _patch(events), connection._socket
        try:
            async with socket.write_lock:             # Bokeh's lock of the socket's messages
                # the frames handed to the socket in this turn of the loop, then awaited: a callback of the next
                # tick (a drag's design, whose threads take the interpreter's lock) starts after they have gone
                written = [WebSocketHandler.write_message(socket, text)
                           for text in (message.header_json, message.metadata_json, message.content_json)]
                for done in written:
                    await done
        except WebSocketClosedError:
            return                                    # the page has gone: its session closes

    return send()


def _patch(events) -> Any:
    """A ``PATCH-DOC`` message of ``events`` (of one document) with its arrays inline, no buffers: Bokeh's
    ``patch_doc.create`` with a serializer that does not defer its bytes."""
    from bokeh.core.serialization import Serializer
    from bokeh.protocol.messages.patch_doc import PatchJson, patch_doc

    doc = events[0].document
    serializer = Serializer(references=doc.models.synced_references, deferred=False)
    content = PatchJson(events=serializer.encode(events))
    doc.models.flush_synced(lambda model: not serializer.has_ref(model))
    return patch_doc(patch_doc.create_header(), {}, content)


def server(text=None, source_dir=None, host=LOOPBACK, port=5006) -> Any:
    """A Bokeh server of the designer (not started), on TOML text (the built-in example without it).

    Raises
    ------
    valvetrain.specification.SpecError
        The specification does not design.
    """
    from bokeh.application import Application
    from bokeh.application.handlers.function import FunctionHandler
    from bokeh.server.connection import ServerConnection
    from bokeh.server.server import Server

    from .session import Session

    Session.start(text, source_dir)
    ServerConnection.send_patch_document = one_message
    origins = [f"{name}:{port}" for name in ("127.0.0.1", "localhost")] + ([f"{host}:{port}"] if host != LOOPBACK
                                                                           else [])
    return Server({"/": Application(FunctionHandler(make_document(text, source_dir)))}, address=host, port=port,
                  allow_websocket_origin=origins, use_index=False, redirect_root=True)

