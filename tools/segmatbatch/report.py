# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""report.html: one self-contained page (inline CSS and script, pictures as data URIs) that opens
offline: counts, PSB metrics per category and overall, failures with their reason, and a sortable
table of every shape with its picture."""
import base64
import html
import os

from .summary import MAIN_METRICS
from .worker import write_text_atomically

_STYLE = """
body{font-family:system-ui,sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;margin:.5em 0 1.5em}
th,td{border:1px solid #ccc;padding:3px 8px;text-align:right}
td.t,th.t{text-align:left}
th.sortable{cursor:pointer;background:#f0f0f0}
th.sortable:after{content:" \\2195";color:#999}
tr.failed{background:#fde8e8}
img.thumb{width:160px;height:auto;display:block}
.muted{color:#777}
"""

# Sorts #shapes by the clicked column (numbers as numbers, blanks last); click again to reverse.
_SCRIPT = """
document.querySelectorAll('#shapes th.sortable').forEach(function (th, col) {
  th.addEventListener('click', function () {
    var body = document.querySelector('#shapes tbody');
    var rows = Array.prototype.slice.call(body.rows);
    var index = th.cellIndex, dir = th.dataset.dir === 'asc' ? -1 : 1;
    th.dataset.dir = dir === 1 ? 'asc' : 'desc';
    rows.sort(function (a, b) {
      var x = a.cells[index].dataset.v, y = b.cells[index].dataset.v;
      if (x === '' || y === '') return (x === '') - (y === '');
      var nx = parseFloat(x), ny = parseFloat(y);
      if (!isNaN(nx) && !isNaN(ny)) return dir * (nx - ny);
      return dir * x.localeCompare(y);
    });
    rows.forEach(function (r) { body.appendChild(r); });
  });
});
"""


def _number(value, digits=4):
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.{digits}f}"
    return str(value)


def _cell(value, text=None, cls=""):
    v = "" if value is None else str(value)
    shown = html.escape(text if text is not None else _number(value))
    return f'<td class="{cls}" data-v="{html.escape(v)}">{shown}</td>'


def _metrics_table(summary):
    if not summary.get("overall"):
        return "<p class=muted>No human segmentations: no PSB metrics.</p>"
    head = "".join(f"<th>{m}</th>" for m in MAIN_METRICS)
    rows = []
    for name, scores in list(summary["categories"].items()) + [("overall", summary["overall"])]:
        cells = "".join(f"<td>{_number(scores.get(m))}</td>" for m in MAIN_METRICS)
        label = f"<b>{name}</b>" if name == "overall" else html.escape(name)
        rows.append(f'<tr><td class="t">{label}</td><td>{scores["models"]}</td>{cells}</tr>')
    return (f'<table id="categories"><thead><tr><th class="t">category</th><th>models</th>{head}'
            f'</tr></thead><tbody>{"".join(rows)}</tbody></table>'
            '<p class=muted>PSB metrics (lower is better): mean over models; CD over the models '
            'where it is defined.</p>')


def _failures(summary):
    items = [f"<li><b>{html.escape(r['name'])}</b>: {html.escape(r['error'])}</li>"
             for r in summary["shapes"] if r["status"] != "ok"]
    items += [f"<li><b>{html.escape(r['name'])}</b>: segmented, no picture: "
              f"{html.escape(r['picture_error'])}</li>"
              for r in summary["shapes"] if r["status"] == "ok" and r.get("picture_error")]
    if not items:
        return "<p>None.</p>"
    return f'<ul id="failures">{"".join(items)}</ul>'


def _thumbnail(out_dir, record):
    path = os.path.join(out_dir, record["name"] + ".png")
    if record["status"] != "ok" or not os.path.isfile(path):
        reason = html.escape(record.get("picture_error", ""), quote=True)
        return f'<td class="t muted" data-v="" title="{reason}">none</td>'
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    return (f'<td class="t" data-v=""><img class="thumb" alt="{html.escape(record["name"])}" '
            f'src="data:image/png;base64,{data}"></td>')


def _shape_rows(out_dir, summary):
    rows = []
    for r in summary["shapes"]:
        metrics = r.get("metrics") or {}
        cells = [_cell(r["name"], cls="t"), _thumbnail(out_dir, r),
                 _cell(r.get("category", ""), cls="t"), _cell(r["status"], cls="t"),
                 _cell(r.get("parts")), _cell(r.get("seconds"), _number(r.get("seconds"), 2)),
                 _cell(r.get("peak_memory_mb"), _number(r.get("peak_memory_mb"), 0))]
        cells += [_cell(metrics.get(m)) for m in MAIN_METRICS]
        cells.append(_cell(r.get("error", ""), cls="t"))
        cls = ' class="failed"' if r["status"] != "ok" else ""
        rows.append(f"<tr{cls}>{''.join(cells)}</tr>")
    return "".join(rows)


def html_text(out_dir, summary, title="segmat batch report"):
    counts = summary["counts"]
    run = summary.get("run", {})
    headers = ["name", "picture", "category", "status", "parts", "seconds", "peak MB"] + \
        MAIN_METRICS + ["error"]
    th = "".join(
        f'<th class="{"t " if h in ("name", "picture", "category", "status", "error") else ""}'
        f'{"" if h == "picture" else "sortable"}">{h}</th>' for h in headers)
    facts = ", ".join(f"{k}: {html.escape(str(v))}" for k, v in run.items()
                      if k in ("input", "shard", "jobs", "wall_seconds", "finished_at", "merged")
                      and v is not None)
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>{_STYLE}</style></head><body>
<h1>{html.escape(title)}</h1>
<p id="counts">{counts['shapes']} shapes: {counts['ok']} segmented, {counts['failed']} failed{
    f", {counts['pictures_failed']} without picture" if counts.get('pictures_failed') else ""}.
<span class=muted>{facts}</span></p>
<h2>PSB metrics</h2>{_metrics_table(summary)}
<h2>Failures</h2>{_failures(summary)}
<h2>Shapes</h2><p class=muted>Click a column title to sort.</p>
<table id="shapes"><thead><tr>{th}</tr></thead><tbody>{_shape_rows(out_dir, summary)}</tbody>
</table>
<script>{_SCRIPT}</script>
</body></html>
"""


def write(out_dir, summary):
    write_text_atomically(os.path.join(out_dir, "report.html"), html_text(out_dir, summary))
