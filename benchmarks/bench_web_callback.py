"""The designer's server side of a drag in this process (issue 25): the processor time of the callback of a drag of
the built-in example's nose handle (9.5 and 9.6 mm in turn, as the page sends it) with the making of the messages to
the page, as the server makes them: one message of the callback's changes where the package sends them so
(:func:`valvetrain.web.one_message`), else one per change.

Run on demand with the tree to measure first on the path, this tree's and another's in turn, e.g.
``PYTHONPATH=/work/main/src python benchmarks/bench_web_callback.py; PYTHONPATH=src python
benchmarks/bench_web_callback.py``: processor time, which the other processes of a loaded machine leave about as it
is (the wall time of the whole redraw is ``bench_web.py``'s).
"""

import argparse
import statistics
import time

from bokeh.document import Document
from bokeh.protocol import Protocol

import valvetrain
from valvetrain import web
from valvetrain.web.app import Designer
from valvetrain.web.session import Session


def main(drags=20):
    designer = Designer(Document(), Session.start())
    designer.start_sweep = lambda: None          # the sweep: in a worker thread, after the page has drawn
    protocol, events = Protocol(), []
    designer.doc.on_change(events.append)
    batched = hasattr(web, "one_message")

    def drag(number):
        handles = dict(designer.handles["lift"].data)
        events.clear()
        start = time.process_time()
        designer.on_handles("lift", "data", handles, {**handles, "y": [9.5 if number % 2 else 9.6]})
        for batch in [events] if batched else [[e] for e in events]:
            protocol.create("PATCH-DOC", batch)
        return 1e3 * (time.process_time() - start)

    for number in range(4):
        drag(number)
    times = [drag(number) for number in range(drags)]
    print(f"{valvetrain.__file__}: the callback of a drag with its messages made: median {statistics.median(times):.1f} "
          f"ms of processor time ({'one message' if batched else 'a message per change'}, {len(events)} changes)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("drags", nargs="?", type=int, default=20, help="drags of the nose handle (default 20)")
    main(parser.parse_args().drags)
