"""The report of a tolerance study (``valvetrain tolerance``, ``tolerance.html``): the tolerances, a table of the
checks that fail in some sample (probability of failure, its 95 % interval, the tolerance that drives it most) and
the histograms of their margins and of the dynamics headlines, drawn as inline SVG."""

from html import escape

from ..bibliography import cite
from ..locale import check_text
from .i18n import TOLERANCE_TEXT
from .names import has_name, label

CITES = {name: f'<span class="cite">{escape(cite(key))}</span>'
         for name, key in (("devroye", "devroye1986"), ("wilson", "wilson1927"))}
"""The works the method's text cites, as the bibliography names them (not translated)."""

WIDTH, HEIGHT = 320, 120
"""Size of a histogram, SVG pixels."""


def histogram_svg(histogram, mark=None) -> str:
    """An SVG bar chart of a histogram (``edges``, ``counts``), with a vertical line at ``mark`` (the bound: margin
    0) where it lies in the range."""
    edges, counts = histogram["edges"], histogram["counts"]
    low, high, top = edges[0], edges[-1], max(max(counts), 1)
    span = high - low

    def x(v):
        return (v - low) / span * WIDTH

    bars = "".join(f'<rect x="{x(a):.1f}" y="{HEIGHT - c / top * (HEIGHT - 14):.1f}" width="{max(x(b) - x(a) - 1, 0.5):.1f}" '
                   f'height="{c / top * (HEIGHT - 14):.1f}" fill="#4878a8"/>'
                   for a, b, c in zip(edges[:-1], edges[1:], counts, strict=True))
    line = (f'<line x1="{x(mark):.1f}" x2="{x(mark):.1f}" y1="0" y2="{HEIGHT}" stroke="#c03030" stroke-width="1.5"/>'
            if mark is not None and low <= mark <= high else "")
    labels = (f'<text x="0" y="10" font-size="10">{low:.4g}</text>'
              f'<text x="{WIDTH}" y="10" font-size="10" text-anchor="end">{high:.4g}</text>')
    return f'<svg width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}">{bars}{line}{labels}</svg>'


def valve_name(valve) -> str:
    """A valve's name as the designer gave it (HTML, marked as a name: it is not translated)."""
    return f'<span class="name">{escape(valve)}</span>'


def check_name(entry, lang) -> str:
    """A check of the study in ``lang`` (HTML): the valve, then the check's text from the catalogue."""
    name = escape(check_text(entry["code"], entry["params"], lang))
    return f"{valve_name(entry['valve'])}: {name}" if entry["valve"] else name


def key_name(key, lang) -> str:
    """A tolerance's key in ``lang`` (HTML): the valve, then the key's name and unit
    (:func:`valvetrain.report.names.label`); the key as the file gives it where it has no name."""
    if not has_name(key):
        return f'<code class="name">{escape(key)}</code>'
    parts = key.split(".")
    name = escape(label(key, lang))
    return f"{valve_name(parts[1])}: {name}" if parts[0] == "valves" and len(parts) > 2 else name


def report_html(result, lang="en") -> str:
    """The HTML text of the report of a tolerance study's ``result`` (:func:`valvetrain.tolerance.summary`)."""
    t = TOLERANCE_TEXT[lang]
    rows = [f"<tr><td>{key_name(x['key'], lang)} <code class=\"name\">{escape(x['key'])}</code></td>"
            f"<td>{t[x['distribution']]}</td><td>{x['nominal']:.6g}</td>"
            f"<td>{x.get('half_range', x.get('sigma', ''))}</td><td>{x.get('low', '')}...{x.get('high', '')}</td></tr>"
            for x in result["tolerances"]]
    tolerances = (f"<h2>{t['tolerances']}</h2><table><tr><th>{t['key']}</th><th>{t['distribution']}</th>"
                  f"<th>{t['nominal']}</th><th>{t['spread']}</th><th>{t['range']}</th></tr>{''.join(rows)}</table>")
    failing = sorted(((c["probability"], cid) for cid, c in result["checks"].items() if c["failures"]), reverse=True)
    lines, figures = [], []
    for p, cid in failing:
        c = result["checks"][cid]
        drivers = {k: v for k, v in c["sensitivities"].items() if v is not None}
        driver = max(drivers, key=lambda k: abs(drivers[k])) if drivers else None
        low, high = c["confidence_95"]
        name = check_name(c, lang)
        severity = t["severities"][c["severity"]] + (f", {t['accepted']}" if c["accepted"] else "")
        lines.append(f"<tr><td>{name}</td><td>{severity}</td><td>{c['failures']} / "
                     f"{c['samples']}</td><td>{p:.4g}</td><td>{low:.4g}...{high:.4g}</td><td>"
                     + (f"{key_name(driver, lang)} ({drivers[driver]:+.2f})" if driver else t["none"]) + "</td></tr>")
        if c["margin"] is not None:
            figures.append(f"<figure>{histogram_svg(c['margin']['histogram'], 0.0)}<figcaption>{name}: "
                           f"{t['margin']}</figcaption></figure>")
    checks = (f"<h2>{t['failures']}</h2>" + (
        f"<table><tr><th>{t['check']}</th><th>{t['severity']}</th><th>{t['failed']}</th><th>{t['probability']}</th>"
        f"<th>{t['confidence']}</th><th>{t['driver']}</th></tr>{''.join(lines)}</table>" if lines else
        f"<p>{t['no_failures']}</p>") + "".join(figures))
    heads = "".join(f"<figure>{histogram_svg(d['histogram'])}<figcaption>{valve_name(valve)}: {t['headlines'][h]}"
                    f"</figcaption></figure>"
                    for valve, hs in result["headlines"].items() for h, d in hs.items() if d is not None)
    refused = result["refused"]
    summary = t["summary"].format(n=result["samples"], method=t[result["method"]], seed=result["seed"],
                                  refused=refused["samples"], p=refused["probability"])
    return (f'<!DOCTYPE html><html lang="{lang}"><head><meta charset="utf-8"><title>{t["title"]}</title>'
            "<style>body{font-family:sans-serif;max-width:60em;margin:auto}table{border-collapse:collapse}"
            "td,th{border:1px solid #bbb;padding:2px 6px}figure{display:inline-block;margin:6px}</style></head>"
            f"<body><h1>{t['title']}</h1><p>{summary}</p><p>{t['method_text'].format(**CITES)}</p>{tolerances}{checks}"
            + (f"<h2>{t['dynamics']}</h2>{heads}" if heads else "") + "</body></html>\n")
