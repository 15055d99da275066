"""Peak memory and throughput of a long four-bar sweep: ``python benchmarks/stream_memory.py
N [stream|run]`` (run it under ``/usr/bin/time -v`` for the peak RSS).

``stream``: :func:`polygons.sweep.stream` chunk by chunk with the summaries on the stream
(:class:`polygons.sweep.Extremes`), nothing kept; ``run``: :func:`polygons.sweep.run`, every
result row preallocated (today's in-memory sweep).  Prints positions per second of the solve
loop (planning excluded).
"""
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from polygons.scene import load_scene  # noqa: E402
from polygons.streams import Extremes, plan_stream, stream  # noqa: E402
from polygons.sweep import run  # noqa: E402


def main(argv):
    n = int(float(argv[0]))
    mode = argv[1] if len(argv) > 1 else "stream"
    scene = load_scene(ROOT / "cases/s001-we6.toml")
    st = plan_stream(scene, n)
    t = time.perf_counter_ns()
    if mode == "stream":
        ext = Extremes()
        for _, xs, res in stream(st):
            ext.add_chunk(xs, res)
        done = ext.n
    else:
        res = run(st.prog, st.inputs(0, n))
        done = len(res["margin"])
    dt = (time.perf_counter_ns() - t) / 1e9
    print(f"{mode}: {done} positions in {dt:.2f} s = {done / dt / 1e6:.2f} M positions/s")


if __name__ == "__main__":
    main(sys.argv[1:])
