"""The designer's server side of a drag in this process (issues 25 and 40): the processor time of the callbacks of a
drag of the built-in example's nose handle (9.5 mm and up by 0.001 mm a drag, as the page sends them: a move of the
pointer, designed and drawn, then the release at the same place, kept) with the making of the messages to the page, as the
server makes them: one message of the callback's changes where the package sends them so
(:func:`valvetrain.web.one_message`), else one per change.  A tree before issue 40 (no live drag) has its release
alone measured.

Run on demand with the tree to measure first on the path, this tree's and another's in turn, e.g.
``PYTHONPATH=/work/main/src python benchmarks/bench_web_callback.py; PYTHONPATH=src python
benchmarks/bench_web_callback.py``: processor time, which the other processes of a loaded machine leave about as it
is (the wall time of the whole redraw is ``bench_web.py``'s).
"""

import argparse
import statistics
import time

from bokeh.document import Document
from bokeh.document.events import DocumentPatchedEvent
from bokeh.protocol import Protocol

import valvetrain
from valvetrain import web
from valvetrain.web.app import Designer
from valvetrain.web.session import Session


def main(drags=20):
    designer = Designer(Document(), Session.start())
    designer.start_sweep = lambda: None          # the sweep: in a worker thread, after the page has drawn
    protocol, events = Protocol(), []
    # the changes Bokeh's server sends (not the callbacks added to the document, e.g. the release's next tick)
    designer.doc.on_change(lambda e: events.append(e) if isinstance(e, DocumentPatchedEvent) else None)
    batched = hasattr(web, "one_message")

    live = hasattr(designer, "on_request")

    def call(kind, y, number):
        if live:
            designer.on_request("data", {}, {"kind": [kind], "seq": [number], "plot": ["lift"], "name": ["nose"],
                                             "x": [0.0], "y": [y], "text": [""]})
        else:
            handles = dict(designer.handles["lift"].data)
            designer.on_handles("lift", "data", handles, {**handles, "y": [y]})

    def timed(kind, y, number):
        events.clear()
        start = time.process_time()
        call(kind, y, number)
        for batch in [events] if batched else [[e] for e in events]:
            protocol.create("PATCH-DOC", batch)
        return 1e3 * (time.process_time() - start)

    def drag(number):
        y = 9.5 + 0.001 * number                 # a new position: designed anew, not kept from an earlier drag
        return (timed("move", y, 2 * number) if live else 0.0), timed("end", y, 2 * number + 1)

    for number in range(4):
        drag(number)
    moves, releases = zip(*[drag(number) for number in range(drags)], strict=True)
    print(f"{valvetrain.__file__}: the callbacks of a drag with their messages made, median processor time: "
          + (f"a move {statistics.median(moves):.1f} ms, " if live else "")
          + f"the release {statistics.median(releases):.1f} ms ({'one message' if batched else 'a message per change'}, "
          f"{len(events)} changes)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("drags", nargs="?", type=int, default=20, help="drags of the nose handle (default 20)")
    main(parser.parse_args().drags)
