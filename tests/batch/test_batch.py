# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""segmat_batch on three bundled PSB meshes: outputs and metrics (equal to segmat_eval --psb),
shards plus merge equal to one run, a crashing and a hanging shape failing alone, a killed run
finishing on restart without redoing finished shapes, the report in a headless browser."""
import csv
import json
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

import fixtures

METRICS = ["RI", "CD", "HD", "GCE", "LCE"]

# Stands in for segmat_mesh (SEGMAT_MESH): copies the reference run's outputs for a shape (no
# computation), crashes on 246 (after a colour-coded message, as VTK's log writes) or hangs on
# 41 when asked, and logs every call.
FAKE_MESH = """#!/bin/sh
name=$(basename "$1" .off)
echo "$name" >> "{log}"
case "{mode}:$name" in
  crash-hang:246) printf '\\033[31mERR| vtkThing: bad X server\\033[0m\\n\\033[0m\\n' >&2; kill -SEGV $$ ;;
  crash-hang:41) exec sleep 600 ;;
esac
[ -n "{delay}" ] && sleep {delay}
cp "{reference}/$name.seg" "$3.seg" && cp "{reference}/$name.ply" "$3.ply" || exit 1
echo '{{"parts": 1, "seconds": {{"load": 0.0}}}}'
"""


def load_summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


class BatchTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="segmat_batch_test")
        cls.psb = fixtures.make_psb_layout(os.path.join(cls.tmp, "psb"))
        cls.single = os.path.join(cls.tmp, "single")
        cls.status, _, cls.err = fixtures.run(
            [fixtures.program("segmat_batch"), cls.psb, "-o", cls.single, "--jobs", "2"],
            {"DISPLAY": ""})

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def batch(self, *args, env=None):
        return fixtures.run([fixtures.program("segmat_batch"), *args], env)

    def fake_mesh(self, mode, delay=""):
        log = os.path.join(self.tmp, f"calls_{mode}_{time.monotonic_ns()}.log")
        path = log[:-4] + ".sh"
        with open(path, "w") as f:
            f.write(FAKE_MESH.format(log=log, mode=mode, delay=delay, reference=self.single))
        os.chmod(path, 0o755)
        return path, log

    def test_outputs_per_shape_and_summary(self):
        self.assertEqual(self.status, 0, self.err)
        summary = load_summary(self.single)
        self.assertEqual([s["name"] for s in summary["shapes"]], fixtures.MODELS)
        self.assertEqual(summary["counts"],
                         {"shapes": 3, "ok": 3, "failed": 0, "pictures_failed": 0})
        for shape in summary["shapes"]:
            name = shape["name"]
            labels = fixtures.read_labels(os.path.join(self.single, name + ".seg"))
            with open(os.path.join(fixtures.DATA, f"psb{name}", f"{name}.off")) as f:
                faces = int(f.read().split()[2])
            self.assertEqual(len(labels), faces)
            self.assertEqual(shape["parts"], len(set(labels)))
            self.assertTrue(os.path.getsize(os.path.join(self.single, name + ".png")) > 1000)
            self.assertIn("segment", shape["stages"])
            self.assertGreater(shape["peak_memory_mb"], 1.0)
        self.assertEqual(set(summary["categories"]), {"Glasses", "Bird", "Bearing"})
        with open(os.path.join(self.single, "summary.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["name"] for r in rows], fixtures.MODELS)
        self.assertEqual([r["status"] for r in rows], ["ok"] * 3)

    def test_folder_of_a_mesh_and_a_cloud(self):
        folder = os.path.join(self.tmp, "mixed")
        os.makedirs(folder)
        with open(os.path.join(fixtures.DATA, "psb346", "346.off")) as f:
            words = f.read().split()
        count = int(words[1])
        with open(os.path.join(folder, "bearing.xyz"), "w") as f:
            for i in range(count):
                f.write(" ".join(words[4 + 3 * i:7 + 3 * i]) + "\n")
        os.symlink(os.path.join(fixtures.DATA, "psb246", "246.off"),
                   os.path.join(folder, "bird.off"))
        out = os.path.join(self.tmp, "mixed_out")
        status, _, err = self.batch(folder, "-o", out, "--jobs", "2", env={"DISPLAY": ""})
        self.assertEqual(status, 0, err)
        shapes = {s["name"]: s for s in load_summary(out)["shapes"]}
        self.assertEqual((shapes["bearing"]["kind"], shapes["bird"]["kind"]), ("cloud", "mesh"))
        labels = fixtures.read_labels(os.path.join(out, "bearing.labels"))
        self.assertEqual(len(labels), count)
        self.assertEqual(shapes["bearing"]["parts"], len(set(labels) - {-1}))
        for name in ("bearing.pcd", "bearing.ply", "bearing.png", "bird.seg", "bird.png"):
            self.assertTrue(os.path.isfile(os.path.join(out, name)), name)
        self.assertIsNone(shapes["bird"]["metrics"])  # no human segmentation in this folder

    def test_picture_has_the_ply_colours(self):
        colors = fixtures.label_colors(os.path.join(self.single, "246.seg"),
                                       os.path.join(self.single, "246.ply"))
        w, h, share, counts = fixtures.pixels_by_color(os.path.join(self.single, "246.png"),
                                                       colors.values())
        self.assertEqual((w, h), (480, 360))
        self.assertTrue(0.1 <= share <= 0.9)
        self.assertTrue(all(n > 0 for n in counts.values()), counts)

    def test_metrics_equal_segmat_eval(self):
        status, out, err = fixtures.run([fixtures.program("segmat_eval"), "--psb", self.psb,
                                         "--pred", self.single, "--json"])
        self.assertEqual(status, 0, err)
        reference = json.loads(out)
        summary = load_summary(self.single)
        for shape in summary["shapes"]:
            for m in METRICS:
                self.assertAlmostEqual(shape["metrics"][m], reference["models"][shape["name"]][m],
                                       places=9)
        for name, scores in reference["categories"].items():
            for m in METRICS:
                self.assertAlmostEqual(summary["categories"][name][m], scores[m], places=9)
        for m in METRICS:
            self.assertAlmostEqual(summary["overall"][m], reference["overall"][m], places=9)

    def test_three_shards_and_merge_equal_one_run(self):
        shards = []
        for k in range(3):
            out = os.path.join(self.tmp, f"shard{k}")
            status, _, err = self.batch(self.psb, "-o", out, "--shard", f"{k}/3", "--no-png",
                                        "--jobs", "1")
            self.assertEqual(status, 0, err)
            self.assertEqual(len(load_summary(out)["shapes"]), 1)
            shards.append(out)
        merged = os.path.join(self.tmp, "merged")
        status, _, err = self.batch("--merge", "-o", merged, *shards)
        self.assertEqual(status, 0, err)
        one, all_ = load_summary(self.single), load_summary(merged)
        self.assertEqual([s["name"] for s in all_["shapes"]], fixtures.MODELS)
        for name in fixtures.MODELS:
            with open(os.path.join(self.single, name + ".seg")) as a, \
                    open(os.path.join(merged, name + ".seg")) as b:
                self.assertEqual(a.read(), b.read())
        self.assertEqual(one["overall"], all_["overall"])
        self.assertEqual(one["categories"], all_["categories"])

    def test_crash_and_hang_fail_alone(self):
        fake, _ = self.fake_mesh("crash-hang")
        out = os.path.join(self.tmp, "crash")
        start = time.monotonic()
        status, _, err = self.batch(self.psb, "-o", out, "--no-png", "--timeout", "3",
                                    env={"SEGMAT_MESH": fake})
        self.assertLess(time.monotonic() - start, 120)
        self.assertEqual(status, 1, err)
        shapes = {s["name"]: s for s in load_summary(out)["shapes"]}
        self.assertEqual(shapes["346"]["status"], "ok")
        self.assertEqual(shapes["246"]["status"], "failed")
        # The reason is the last line with text, without the terminal colour codes around it.
        self.assertTrue(shapes["246"]["error"].endswith(
            ".sh crashed (SIGSEGV): ERR| vtkThing: bad X server"), shapes["246"]["error"])
        self.assertEqual(shapes["41"]["status"], "failed")
        self.assertIn("timeout", shapes["41"]["error"])
        self.assertFalse(os.path.exists(os.path.join(out, "246.seg")))
        with open(os.path.join(out, "report.html")) as f:
            page = f.read()
        self.assertIn("crashed (SIGSEGV)", page)
        # The hanging program was killed with its process group.
        ps = subprocess.run(["ps", "-eo", "args"], capture_output=True, text=True).stdout
        self.assertNotIn("sleep 600", ps)

    def test_memory_limit_fails_the_shape_with_the_reason(self):
        # 20 MB of address space cannot even hold segmat_mesh's shared libraries.
        out = os.path.join(self.tmp, "memory")
        status, _, err = self.batch(self.psb, "-o", out, "--no-png", "--shard", "0/3",
                                    "--max-memory", "20")
        self.assertEqual(status, 1, err)
        (shape,) = load_summary(out)["shapes"]
        self.assertEqual(shape["status"], "failed")
        self.assertIn("out of memory (--max-memory 20 MB)", shape["error"])

    def test_picture_that_cannot_be_drawn_leaves_the_shape_segmented(self):
        fake, calls = self.fake_mesh("fast")
        out = os.path.join(self.tmp, "nodisplay")
        number = next(n for n in range(977, 1100) if not os.path.exists(f"/tmp/.X11-unix/X{n}"))
        status, _, err = self.batch(self.psb, "-o", out, "--shard", "0/3",
                                    env={"SEGMAT_MESH": fake, "DISPLAY": f":{number}"})
        self.assertEqual(status, 0, err)
        self.assertIn("1 segmented shapes have no picture", err)
        summary = load_summary(out)
        self.assertEqual(summary["counts"],
                         {"shapes": 1, "ok": 1, "failed": 0, "pictures_failed": 1})
        (shape,) = summary["shapes"]
        self.assertIn(f"cannot draw on X display ':{number}'", shape["picture_error"])
        # The message names the picture where it would have gone, not the temporary folder.
        self.assertIn(os.path.join(out, "41.png") + ":", shape["picture_error"])
        self.assertEqual(shape["outputs"], ["41.ply", "41.seg"])
        self.assertIsNotNone(shape["metrics"])  # scored all the same
        with open(os.path.join(out, "summary.csv")) as f:
            self.assertIn("cannot draw on X display", next(csv.DictReader(f))["picture_error"])
        with open(os.path.join(out, "report.html")) as f:
            self.assertIn("1 without picture", f.read())
        # A plain rerun keeps the shape; --retry-failed segments it again and draws it.
        status, _, err = self.batch(self.psb, "-o", out, "--shard", "0/3",
                                    env={"SEGMAT_MESH": fake, "DISPLAY": f":{number}"})
        self.assertEqual((status, load_summary(out)["counts"]["pictures_failed"]), (0, 1), err)
        status, _, err = self.batch(self.psb, "-o", out, "--shard", "0/3", "--retry-failed",
                                    env={"SEGMAT_MESH": fake, "DISPLAY": ""})
        self.assertEqual(status, 0, err)
        (shape,) = load_summary(out)["shapes"]
        self.assertEqual(shape["picture_error"], "")
        self.assertIn("41.png", shape["outputs"])
        with open(calls) as f:
            self.assertEqual(f.read().split(), ["41", "41"])

    def test_killed_run_restarts_without_redoing_finished_shapes(self):
        slow, first_log = self.fake_mesh("slow", delay="2")
        out = os.path.join(self.tmp, "killed")
        runner = subprocess.Popen([fixtures.program("segmat_batch"), self.psb, "-o", out,
                                   "--no-png", "--jobs", "1"],
                                  env=dict(os.environ, SEGMAT_MESH=slow),
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        first = os.path.join(out, "shapes", "41.json")
        deadline = time.monotonic() + 60
        while not os.path.exists(first) and time.monotonic() < deadline:
            time.sleep(0.05)
        runner.send_signal(signal.SIGKILL)
        runner.wait()
        self.assertTrue(os.path.exists(first))
        self.assertFalse(os.path.exists(os.path.join(out, "summary.json")))
        with open(first) as f:
            finished = json.load(f)

        fast, second_log = self.fake_mesh("fast")
        status, _, err = self.batch(self.psb, "-o", out, "--no-png", "--jobs", "1",
                                    env={"SEGMAT_MESH": fast})
        self.assertEqual(status, 0, err)
        self.assertIn("1 of 3 shapes already finished", err)
        with open(second_log) as f:
            self.assertEqual(f.read().split(), ["246", "346"])
        summary = load_summary(out)
        self.assertEqual(summary["counts"]["ok"], 3)
        self.assertEqual(summary["shapes"][0], finished)
        self.assertEqual(os.listdir(os.path.join(out, ".partial")), [])

    def test_report_loads_in_headless_chromium(self):
        browser = shutil.which("chromium") or shutil.which("chromium-browser")
        self.assertIsNotNone(browser, "chromium is needed (scripts/install_deps.sh installs it)")
        with open(os.path.join(self.single, "report.html")) as f:
            page = f.read()
        # A probe that runs before the page's own script: records errors, then after load
        # counts the table's rows and the pictures that decoded, and sorts by parts.
        probe = """<script>
var probeErrors = [];
window.addEventListener('error', function (e) { probeErrors.push(String(e.message)); }, true);
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var loaded = imgs.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  var ths = Array.prototype.slice.call(document.querySelectorAll('#shapes th'));
  ths.filter(function (t) { return t.textContent === 'parts'; })[0].click();
  var parts = Array.prototype.map.call(document.querySelectorAll('#shapes tbody tr'),
    function (r) { return r.cells[4].dataset.v; }).join(',');
  var out = document.createElement('pre');
  out.id = 'probe';
  out.textContent = 'errors=' + probeErrors.length + ' rows=' +
    document.querySelectorAll('#shapes tbody tr').length + ' images=' + imgs.length +
    ' loaded=' + loaded + ' parts=' + parts;
  document.body.appendChild(out);
});
</script>"""
        probed = os.path.join(self.tmp, "probed.html")
        with open(probed, "w") as f:
            f.write(page.replace("<head>", "<head>" + probe, 1))
        profile = tempfile.mkdtemp(prefix="chromium", dir=self.tmp)
        p = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu",
                            "--disable-background-networking", "--no-first-run",
                            f"--user-data-dir={profile}", "--virtual-time-budget=5000",
                            "--dump-dom", "file://" + probed],
                           capture_output=True, text=True, timeout=120)
        m = re.search(r'<pre id="probe">([^<]*)</pre>', p.stdout)
        self.assertIsNotNone(m, p.stderr[-2000:])
        fields = dict(kv.split("=") for kv in m.group(1).split())
        self.assertEqual(fields["errors"], "0")
        self.assertEqual(fields["rows"], "3")
        self.assertEqual(fields["images"], "3")
        self.assertEqual(fields["loaded"], "3")
        parts = [int(v) for v in fields["parts"].split(",")]
        self.assertEqual(parts, sorted(parts))


if __name__ == "__main__":
    unittest.main()
