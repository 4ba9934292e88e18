# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""summary.json and summary.csv of a batch: per shape, and the PSB metrics per category and
overall, averaged as segmat_eval --psb does (mean over models; CD over the models where it is
defined)."""
import csv
import io
import json
import math

from . import inputs
from .worker import write_text_atomically

# Metrics in summary.json; the first five are the PSB's usual ones (segmat_eval --help).
METRICS = ["RI", "CD", "HD", "GCE", "LCE", "Rm", "Rf", "GCEf", "LCEf"]
MAIN_METRICS = METRICS[:5]


def _mean_scores(per_model):
    """Means of a list of per-model metric dicts (segmat_eval's JSON); None when empty."""
    if not per_model:
        return None
    mean = {"models": len(per_model)}
    for key in METRICS:
        values = [m[key] for m in per_model if m.get(key) is not None
                  and not (isinstance(m[key], float) and math.isnan(m[key]))]
        mean[key] = sum(values) / len(values) if values and (key == "CD" or
                                                             len(values) == len(per_model)) else None
    mean["cd_models"] = sum(1 for m in per_model if m.get("CD") is not None)
    return mean


def aggregate(records):
    """{"overall": means over every scored shape, "categories": {name: means}} (PSB order)."""
    scored = [r for r in records if r["status"] == "ok" and r.get("metrics")]
    categories = {}
    for name in inputs.PSB_CATEGORIES:
        mean = _mean_scores([r["metrics"] for r in scored if r.get("category") == name])
        if mean:
            categories[name] = mean
    return {"overall": _mean_scores([r["metrics"] for r in scored]), "categories": categories}


def build(records, run):
    """The summary.json object: run facts, counts, shapes (sorted by name), metrics."""
    records = sorted(records, key=lambda r: inputs.sort_key(r["name"]))
    failed = [r for r in records if r["status"] != "ok"]
    unpictured = [r for r in records if r["status"] == "ok" and r.get("picture_error")]
    summary = {"run": run,
               "counts": {"shapes": len(records), "ok": len(records) - len(failed),
                          "failed": len(failed), "pictures_failed": len(unpictured)},
               "shapes": records}
    summary.update(aggregate(records))
    return summary


def _stage_names(records):
    names = []
    for r in records:
        for stage in r.get("stages", {}):
            if stage not in names:
                names.append(stage)
    return names


def csv_text(summary):
    """One row per shape: name, category, status, parts, seconds, peak memory, the five main
    PSB metrics, seconds per stage, error, picture error."""
    records = summary["shapes"]
    stages = _stage_names(records)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["name", "category", "kind", "status", "parts", "seconds", "peak_memory_mb"]
                    + MAIN_METRICS + ["seconds_" + s for s in stages] + ["error", "picture_error"])
    for r in records:
        metrics = r.get("metrics") or {}
        writer.writerow([r["name"], r.get("category", ""), r.get("kind", ""), r["status"],
                         _cell(r.get("parts")), _cell(r.get("seconds")),
                         _cell(r.get("peak_memory_mb"))]
                        + [_cell(metrics.get(k)) for k in MAIN_METRICS]
                        + [_cell(r.get("stages", {}).get(s)) for s in stages]
                        + [r.get("error", ""), r.get("picture_error", "")])
    return out.getvalue()


def _cell(value):
    return "" if value is None else value


def write(out_dir, summary):
    """Writes summary.json and summary.csv into OUT_DIR, each whole or not at all."""
    write_text_atomically(f"{out_dir}/summary.json", json.dumps(summary, indent=1) + "\n")
    write_text_atomically(f"{out_dir}/summary.csv", csv_text(summary))
