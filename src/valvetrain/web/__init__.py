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
import json
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
    """Bokeh's ``ServerConnection.send_patch_document`` sending the changes of a callback to the page in one message:
    each change is queued and the first of the writes that the server awaits after the callback sends all that
    are queued (the rest find the queue empty), every frame of the message handed to the socket in one turn of the
    server's event loop.

    Notes
    -----
    Bokeh sends a message per change (a redraw of the designer changes about ten models: the curves, the handles,
    the checks, the card, the stamp ...), each as four or more frames of the web socket, each waking the page; the
    page applies one message's changes in order, as it did the messages'.  The values are those the models hold
    when the message is made, after the callback: its last, as the last message would have brought.

    A message is three frames and two more per array (its reference, then its bytes): a release's redraw of the
    curves is 61.  Bokeh writes each and awaits it before the next (``Message.send``), a turn of the event loop
    each, and the callbacks of the next tick ran between them: a drag's release started its design's and its
    sweep's threads after the first frame.  Here the frames are written at once, then awaited: those callbacks
    run after the message has gone.  Its small arrays go within its text (:func:`_inline`): a release's redraw is
    three frames, not 61, which the page received as 61 tasks over up to 70 ms at a load of 5-7 (a frame's arrival
    in the page logged against the server's write).  The socket sends at once (TCP_NODELAY): Bokeh and Tornado leave
    Nagle's algorithm on, which held a frame written after a small one (Bokeh's OK to the page's request) until the
    page's TCP stack acknowledged that one, a delayed ACK of up to 40 ms: the page had a release's redraw 50-75 ms
    after the server wrote it at a load of 2-4, idle or not.
    """
    from tornado.websocket import WebSocketClosedError, WebSocketHandler

    queue = connection.__dict__.setdefault("_queued_changes", [])
    queue.append(event)

    async def send():
        if not queue:
            return
        events = list(queue)
        queue.clear()
        message, socket = _inline(connection.protocol.create("PATCH-DOC", events)), connection._socket
        frames = [(message.header_json, False), (message.metadata_json, False), (message.content_json, False)]
        for buffer in message.buffers:
            frames += [(json.dumps(buffer.ref), False), (buffer.to_bytes(), True)]
        try:
            socket.set_nodelay(True)                  # each frame sent at once: Nagle's algorithm held it for the
            async with socket.write_lock:             # page's delayed ACK (40 ms); Bokeh's lock of the messages
                written = [WebSocketHandler.write_message(socket, frame, binary) for frame, binary in frames]
                for done in written:
                    await done
        except WebSocketClosedError:
            return                                    # the page has gone: its session closes

    return send()


INLINE_BYTES = 16384
"""The largest array sent within a message's text (base64, a third more bytes), not as frames of its own: a curve of
the designer is 1-2 kB, the sweep panel's lift-error map 331 kB (base64 of it cost the server 15-30 ms)."""


def _inline(message) -> Any:
    """``message`` (a ``PATCH-DOC`` message as Bokeh makes it) with its buffers of at most :data:`INLINE_BYTES` in its
    content as base64 text (as Bokeh's serializer writes them when it does not defer its bytes), the larger ones kept
    as buffers."""
    from bokeh.core.serialization import Buffer
    from bokeh.protocol.messages.patch_doc import patch_doc

    small = {id(b) for b in message.buffers if len(b.to_bytes()) <= INLINE_BYTES}
    if not small:
        return message

    def inlined(value):
        if isinstance(value, Buffer):
            return value.to_base64() if id(value) in small else value
        if isinstance(value, dict):
            return {k: inlined(v) for k, v in value.items()}
        if isinstance(value, (list, tuple)):
            return [inlined(v) for v in value]
        return value

    out = patch_doc(patch_doc.create_header(), message.metadata, inlined(message.content))
    large = [b for b in message.buffers if id(b) not in small]
    if large:
        out.add_buffers(*large)
    return out


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

