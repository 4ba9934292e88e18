# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""segmat_render and --png: pictures of the right size, every part in its coloured-PLY colour,
the shape filling a sensible share of the picture, with no X server needed."""
import os
import shutil
import subprocess
import tempfile
import unittest

import fixtures


class RenderTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="segmat_render_test")
        cls.mesh = os.path.join(fixtures.DATA, "psb346", "346.off")
        cls.prefix = os.path.join(cls.tmp, "346")
        # --png: segmat_mesh draws its result through segmat_render (no DISPLAY: Xvfb).
        env = {"DISPLAY": ""}
        cls.status, _, cls.err = fixtures.run(
            [fixtures.program("segmat_mesh"), cls.mesh, "-o", cls.prefix, "--png",
             cls.prefix + ".png"], env)
        cls.colors = fixtures.label_colors(cls.prefix + ".seg", cls.prefix + ".ply")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def check_picture(self, path, width, height, colors):
        w, h, share, counts = fixtures.pixels_by_color(path, colors.values())
        self.assertEqual((w, h), (width, height))
        self.assertTrue(0.1 <= share <= 0.9, f"the shape covers {share:.3f} of {path}")
        for label, color in colors.items():
            self.assertGreater(counts[color], 20, f"part {label} colour {color} not in {path}")

    def test_png_option_of_segmat_mesh(self):
        self.assertEqual(self.status, 0, self.err)
        self.assertGreaterEqual(len(self.colors), 2)
        self.check_picture(self.prefix + ".png", 800, 600, self.colors)

    def test_every_view_shows_every_part(self):
        # (Seen from the top, the bearing shows its cap only.)
        for view in ("front", "three-quarter", "all"):
            out = os.path.join(self.tmp, f"view_{view}.png")
            status, _, err = fixtures.run(
                [fixtures.program("segmat_render"), self.mesh, self.prefix + ".seg", "-o", out,
                 "--view", view, "--size", "600x300", "--part-ids"], {"DISPLAY": ""})
            self.assertEqual(status, 0, err)
            self.check_picture(out, 600, 300, self.colors)

    def test_boxes_are_drawn_over_the_parts(self):
        # segmat_mesh --boxes writes the boxes; segmat_render --boxes draws their edges in dark
        # grey (38, 38, 38), a colour no part has, so the picture gains many such pixels.
        prefix = os.path.join(self.tmp, "boxes")
        status, _, err = fixtures.run(
            [fixtures.program("segmat_mesh"), self.mesh, "-o", prefix, "--boxes", "-q"])
        self.assertEqual(status, 0, err)
        dark = {}
        for name, extra in (("plain", []), ("boxes", ["--boxes", prefix + "_boxes.ply"])):
            out = os.path.join(self.tmp, f"{name}.png")
            status, _, err = fixtures.run(
                [fixtures.program("segmat_render"), self.mesh, prefix + ".seg", "-o", out,
                 "--size", "400x300", *extra], {"DISPLAY": ""})
            self.assertEqual(status, 0, err)
            _, _, rows = fixtures.read_png(out)
            dark[name] = sum(1 for row in rows for p in row if max(p) <= 60 and
                             max(p) - min(p) <= 8)
        self.assertGreater(dark["boxes"], dark["plain"] + 200, dark)

    def test_cloud_points_coloured_by_part(self):
        # The mesh's vertices as a cloud, each labelled like its first face.
        with open(self.mesh) as f:
            words = f.read().split()
        nv, nf = int(words[1]), int(words[2])
        coords = words[4:4 + 3 * nv]
        faces = words[4 + 3 * nv:]
        face_labels = fixtures.read_labels(self.prefix + ".seg")
        point_labels = [None] * nv
        pos = 0
        for k in range(nf):
            n = int(faces[pos])
            for v in faces[pos + 1:pos + 1 + n]:
                if point_labels[int(v)] is None:
                    point_labels[int(v)] = face_labels[k]
            pos += n + 1
        cloud = os.path.join(self.tmp, "cloud.xyz")
        with open(cloud, "w") as f:
            for i in range(nv):
                f.write(" ".join(coords[3 * i:3 * i + 3]) + "\n")
        labels = os.path.join(self.tmp, "cloud.labels")
        with open(labels, "w") as f:
            f.write("".join(f"{-1 if l is None else l}\n" for l in point_labels))
        out = os.path.join(self.tmp, "cloud.png")
        status, _, err = fixtures.run([fixtures.program("segmat_render"), cloud, labels, "-o", out],
                                      {"DISPLAY": ""})
        self.assertEqual(status, 0, err)
        used = {l: c for l, c in self.colors.items() if l in point_labels}
        self.check_picture(out, 800, 600, used)

    def test_bad_input_is_named_and_writes_nothing(self):
        short = os.path.join(self.tmp, "short.seg")
        with open(short, "w") as f:
            f.write("0\n1\n")
        out = os.path.join(self.tmp, "never.png")
        status, _, err = fixtures.run([fixtures.program("segmat_render"), self.mesh, short, "-o", out])
        self.assertEqual(status, 2)
        self.assertIn("short.seg", err)
        self.assertFalse(os.path.exists(out))
        status, _, err = fixtures.run([fixtures.program("segmat_render"), self.mesh, short, "-o", out,
                                       "--size", "10x10"])
        self.assertEqual(status, 2)
        self.assertIn("--size", err)

    def test_unusable_display_is_an_error_not_a_crash(self):
        # VTK aborts on a display it cannot open; segmat_render checks the display first.
        number = next(n for n in range(977, 1100) if not os.path.exists(f"/tmp/.X11-unix/X{n}"))
        out = os.path.join(self.tmp, "nowhere.png")
        status, _, err = fixtures.run([fixtures.program("segmat_render"), self.mesh,
                                       self.prefix + ".seg", "-o", out], {"DISPLAY": f":{number}"})
        self.assertEqual(status, 1, err)
        self.assertIn(f"cannot draw on X display ':{number}'", err)
        self.assertFalse(os.path.exists(out))

    def test_one_connection_through_the_drawing(self):
        # An X server resets when its last client leaves and drops the clients that arrive
        # meanwhile; with -terminate it exits instead, so a program that lets go of the display
        # before VTK takes it (a display check, say) finds no server at all.
        read_end, write_end = os.pipe()
        server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_end), "-screen", "0", "1024x768x24", "-nolisten",
             "tcp", "-terminate"], pass_fds=(write_end,), stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end) as f:
            number = f.readline().strip()
        try:
            self.assertTrue(number.isdigit())
            out = os.path.join(self.tmp, "terminate.png")
            status, _, err = fixtures.run([fixtures.program("segmat_render"), self.mesh,
                                           self.prefix + ".seg", "-o", out, "--size", "200x150"],
                                          {"DISPLAY": f":{number}"})
            self.assertEqual(status, 0, err)
            self.check_picture(out, 200, 150, {})
            # The server went with the program's connection: nothing else held it.
            self.assertEqual(server.wait(timeout=30), 0)
        finally:
            if server.poll() is None:
                server.kill()
                server.wait()


if __name__ == "__main__":
    unittest.main()
