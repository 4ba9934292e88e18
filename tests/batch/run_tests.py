# segmat — 3D shape segmentation with the medial axis transform.
# SPDX-License-Identifier: BSD-3-Clause
"""Runs one test module of tests/batch quietly (ctest): prints unittest's report only on failure.
Usage: python3 run_tests.py MODULE; the environment names the build's programs and the data
(SEGMAT_BIN_DIR, SEGMAT_DATA_DIR)."""
import io
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
suite = unittest.defaultTestLoader.loadTestsFromName(sys.argv[1])
stream = io.StringIO()
result = unittest.TextTestRunner(stream=stream, verbosity=2).run(suite)
if not result.wasSuccessful() or not result.testsRun:
    sys.stderr.write(stream.getvalue())
    sys.exit(1)
