"""The report of a tolerance study (``valvetrain tolerance``, ``tolerance.html``): the tolerances, a table of the
checks that fail in some sample (probability of failure, its 95 % interval, the tolerance that drives it most) and
the histograms of their margins and of the dynamics headlines, drawn as inline SVG; of a study by Saltelli's scheme
(``--method sobol``) also the Sobol' indices of those checks and headlines with their intervals, a table with bars."""

from html import escape

from ..bibliography import cite
from ..locale import catalogue, check_text
from .names import has_name, label

CITES = {name: f'<span class="cite">{escape(cite(key))}</span>'
         for name, key in (("devroye", "devroye1986"), ("wilson", "wilson1927"), ("sobol", "sobol2001"),
                           ("saltelli", "saltelli2010"))}
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


INDEX_WIDTH, INDEX_HEIGHT = 200, 24
"""Size of the bars of a tolerance's Sobol' indices, SVG pixels: the index 1 spans the width."""

INDEX_COLOURS = {"first": "#4878a8", "total": "#d08030"}
"""Colours of the bars of the first-order and the total index."""


def indices_svg(entry) -> str:
    """An SVG bar chart of one tolerance's Sobol' indices (``first``, ``total`` and the half-widths of their 95 %
    intervals ``first_95``, ``total_95``): a bar from 0 to each index (the first-order one above) on a scale 0 to 1
    (:data:`INDEX_WIDTH` px), its interval as an error bar; what lies outside [0, 1] is drawn at the edge."""

    def x(v):
        return min(max(v, 0.0), 1.0) * INDEX_WIDTH

    parts = []
    for k, name in enumerate(("first", "total")):
        v, half = entry[name], entry[f"{name}_95"]
        y, mid = 2 + 11 * k, 2 + 11 * k + 4.5
        parts.append(f'<rect x="0" y="{y}" width="{x(v):.1f}" height="9" fill="{INDEX_COLOURS[name]}"/>'
                     f'<line x1="{x(v - half):.1f}" x2="{x(v + half):.1f}" y1="{mid}" y2="{mid}" stroke="#000"/>'
                     + "".join(f'<line x1="{x(e):.1f}" x2="{x(e):.1f}" y1="{mid - 3}" y2="{mid + 3}" stroke="#000"/>'
                               for e in (v - half, v + half)))
    return (f'<svg width="{INDEX_WIDTH}" height="{INDEX_HEIGHT}" viewBox="0 0 {INDEX_WIDTH} {INDEX_HEIGHT}">'
            f'<rect x="0" y="0" width="{INDEX_WIDTH}" height="{INDEX_HEIGHT}" fill="none" stroke="#bbb"/>'
            f'{"".join(parts)}</svg>')


def sobol_section(result, failing, lang) -> str:
    """The Sobol' indices of the checks that fail in some sample (``failing``: their ids) and of the dynamics
    headlines (HTML): a row per tolerance with its first-order and total index, each +- the half-width of its 95 %
    interval, and their bars (:func:`indices_svg`); an output without indices says why."""
    t = catalogue(lang)["tolerance_words"]
    keys = [x["key"] for x in result["tolerances"]]
    outputs = [(check_name(result["checks"][cid], lang), result["checks"][cid]["sobol"]) for cid in failing]
    outputs += [(f"{valve_name(valve)}: {t['headlines'][h]}", entry)
                for valve, hs in result["headline_sobol"].items() for h, entry in hs.items()]
    rows = []
    for name, entry in outputs:
        if entry["indices"] is None:
            rows.append(f'<tr><td>{name}</td><td colspan="4">{t["sobol_reasons"][entry["reason"]]}</td></tr>')
            continue
        for j, key in enumerate(keys):
            e = entry["indices"][key]
            head = f'<td rowspan="{len(keys)}">{name}</td>' if j == 0 else ""
            rows.append(f"<tr>{head}<td>{key_name(key, lang)}</td><td>{e['first']:.3f} ± {e['first_95']:.3f}</td>"
                        f"<td>{e['total']:.3f} ± {e['total_95']:.3f}</td><td>{indices_svg(e)}</td></tr>")
    table = (f"<table><tr><th>{t['output']}</th><th>{t['key']}</th><th>{t['first']}</th><th>{t['total']}</th>"
             f"<th>{t['bars']}</th></tr>{''.join(rows)}</table>" if rows else "")
    return f"<h2>{t['sobol_title']}</h2><p>{t['sobol_text'].format(**CITES)}</p>{table}"


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
    t = catalogue(lang)["tolerance_words"]
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
            + (f"<h2>{t['dynamics']}</h2>{heads}" if heads else "")
            + (sobol_section(result, [cid for _, cid in failing], lang) if result["method"] == "sobol" else "")
            + "</body></html>\n")
