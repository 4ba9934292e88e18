# Python threads calling at once (the GIL is released while C++ computes) get the same labels.
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import segmat


def test_threads_calling_at_once_get_the_same_labels(teddy, teddy_cli, teddy_segmenter):
    expected = teddy_cli[0]
    segmenter = teddy_segmenter[0]
    with ThreadPoolExecutor(max_workers=4) as pool:
        # Two full segmentations (each its own medial step) and four calls on one shared
        # segmenter, with two parameter sets interleaved.
        full = [pool.submit(segmat.segment_mesh, *teddy, threads=t) for t in (1, 2)]
        shared = [pool.submit(segmenter.segment, **({"delta0": 1.0} if i % 2 else {}))
                  for i in range(4)]
        coarse = segmenter.segment(delta0=1.0)
        for future in full + shared[0::2]:
            np.testing.assert_array_equal(future.result(), expected)
        for future in shared[1::2]:
            np.testing.assert_array_equal(future.result(), coarse)
    assert segmenter.mat_computations == 1


def test_the_gil_is_released_while_cpp_computes(teddy_segmenter):
    # With a switch interval far longer than the call, a thread holding the GIL keeps it to the
    # end of the call: the main thread can run before the call returns only if the call let go.
    import sys
    import threading

    segmenter = teddy_segmenter[0]
    started, returned = threading.Event(), []

    def work():
        started.set()
        segmenter.segment(delta0=0.02)
        returned.append(True)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        started.wait()
        ran_during_call = not returned
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert ran_during_call and returned
