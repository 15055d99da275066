"""A student's drawn polygon, as `polygons check --drawing FILE` reads it (JSON or SVG).

**JSON** (``.json``; coordinates in mm on the paper, x to the right, y up)::

    {"diagram": "velocity",                 # or "acceleration"
     "scale": "1 mm = 0.02 m/s",            # or "1 cm = 2 m/s", or a number: SI per mm
     "vertices": {"o": [20, 30], "b": [-70.7, -22.4], "c": [-65.8, 16.2]},
     "vectors": [["o", "b"], ["b", "c"], ["o", "c"]],
     "y": "up"}                             # optional: "down" when y grows down the page

Vertex names are the construction's (``o`` or any fixed point's letter for the pole, ``b``,
``c1``, ``p4_1`` ...: the handout and the interactive page name them); each vector is an arrow
from its first vertex to its second.

**SVG** (what the interactive page saves; user units are mm, y down as in every SVG)::

    <svg xmlns="http://www.w3.org/2000/svg" data-polygons-drawing="velocity"
         data-scale="1 mm = 0.02 m/s" viewBox="0 0 200 150">
      <circle data-vertex="o" cx="100" cy="80" r="0.8"/>
      <line data-from="o" data-to="b" x1="100" y1="80" x2="29.3" y2="102.4"/>
    </svg>

Any element with ``data-vertex`` and ``cx``/``cy`` is a vertex; any element with
``data-from``/``data-to`` is an arrow (its own coordinates are not read: the vertices are).
``transform`` attributes are not applied (the page writes none).  A DOCTYPE or entity is
refused; so is a file over 1 MB, more than :data:`MAX_VERTICES` vertices or
:data:`MAX_VECTORS` arrows, a coordinate beyond ±10 m of paper, and a
scale outside 1e-9 … 1e9 SI units per mm.
"""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Mapping

from .errors import SceneError, show
from .options import scale_per_cm

MAX_BYTES = 1_000_000
MAX_VERTICES = 200
MAX_VECTORS = 500
MAX_MM = 10_000.0
#: the scales accepted, SI units (m/s, m/s²) per mm of paper
MIN_SCALE, MAX_SCALE = 1e-9, 1e9
DIAGRAMS = ("velocity", "acceleration")
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_'′]{0,19}$")


class DrawingError(SceneError):
    """A drawing file that cannot be read (one line naming the file and the key)."""


@dataclass(frozen=True)
class StudentDrawing:
    diagram: str                                  # 'velocity' | 'acceleration'
    scale: float                                  # SI units per mm of paper
    scale_text: str                               # as written
    vertices: Mapping[str, tuple[float, float]]   # name (lower case) -> mm, y up
    vectors: tuple[tuple[str, str], ...]          # arrows, from -> to
    file: str


def _fail(msg: str, file: str, where: str | None = None) -> DrawingError:
    return DrawingError(msg, file=file, where=where)


def read_drawing(path: str) -> StudentDrawing:
    p = Path(path)
    if not p.is_file():
        raise _fail("no such drawing file", path)
    with open(p, "rb") as fh:
        raw = fh.read(MAX_BYTES + 1)
    if len(raw) > MAX_BYTES:
        raise _fail(f"a drawing file is at most {MAX_BYTES:,} bytes", path)
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise _fail("not UTF-8 text", path) from None
    if text.lstrip().startswith("<"):
        return parse_svg(text, path)
    return parse_json(text, path)


def _scale(value, diagram: str, file: str) -> tuple[float, str]:
    if isinstance(value, bool) or value is None:
        raise _fail(f"scale must be text such as '1 mm = 0.02 m/s' or a number (SI per mm), "
                    f"got {show(value)}", file, "scale")
    if isinstance(value, (int, float)):
        if not (math.isfinite(value) and value > 0):
            raise _fail(f"scale must be positive, got {show(value)}", file, "scale")
        if not MIN_SCALE <= value <= MAX_SCALE:
            raise _fail(f"a scale from {MIN_SCALE:g} to {MAX_SCALE:g} SI units per mm, got "
                        f"{show(value)}", file, "scale")
        return float(value), f"1 mm = {value:g} SI"
    per_cm = scale_per_cm(value, diagram, file=file, where="scale", error=DrawingError)
    si = per_cm / 10.0
    if not MIN_SCALE <= si <= MAX_SCALE:
        raise _fail(f"a scale from {MIN_SCALE:g} to {MAX_SCALE:g} SI units per mm, got "
                    f"{show(value)}", file, "scale")
    return si, " ".join(str(value).split())


def _name(value, file: str, where: str) -> str:
    if not isinstance(value, str) or not _NAME.match(value):
        raise _fail(f"a vertex name is a letter followed by up to 19 letters, digits, '_' "
                    f"or primes (b, c1, p4_1), got {show(value)}", file, where)
    return value.lower()


def _coord(value, file: str, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(
            value) or abs(value) > MAX_MM:
        raise _fail(f"a coordinate is a number of mm within ±{MAX_MM:g}, got {show(value)}",
                    file, where)
    return float(value)


def _build(diagram, scale, vertices: dict, vectors: list, file: str) -> StudentDrawing:
    if diagram not in DIAGRAMS:
        raise _fail(f"diagram must be 'velocity' or 'acceleration', got {show(diagram)}",
                    file, "diagram")
    si, text = _scale(scale, diagram, file)
    if len(vertices) > MAX_VERTICES:
        raise _fail(f"at most {MAX_VERTICES} vertices, got {len(vertices)}", file, "vertices")
    if len(vectors) > MAX_VECTORS:
        raise _fail(f"at most {MAX_VECTORS} vectors, got {len(vectors)}", file, "vectors")
    for i, (a, b) in enumerate(vectors):
        for name in (a, b):
            if name not in vertices:
                raise _fail(f"vector {a}{b} names the vertex {name!r}, which is not among "
                            f"the vertices", file, f"vectors[{i}]")
    return StudentDrawing(diagram, si, text, MappingProxyType(dict(vertices)), tuple(vectors),
                          file)


def parse_json(text: str, file: str = "<drawing>") -> StudentDrawing:
    try:
        data = json.loads(text)
    except (ValueError, RecursionError) as exc:
        raise _fail(f"not valid JSON: {' '.join(str(exc).split())[:100]}", file) from None
    if not isinstance(data, dict):
        raise _fail("a drawing is a JSON object with diagram, scale, vertices, vectors", file)
    unknown = set(data) - {"diagram", "scale", "vertices", "vectors", "y"}
    if unknown:
        raise _fail(f"unknown key {show(sorted(unknown)[0])} (keys: diagram, scale, vertices, "
                    f"vectors, y)", file, sorted(unknown)[0])
    for key in ("diagram", "scale", "vertices", "vectors"):
        if key not in data:
            raise _fail(f"missing key {key!r}", file)
    flip = data.get("y", "up")
    if flip not in ("up", "down"):
        raise _fail(f"y must be 'up' or 'down', got {show(flip)}", file, "y")
    raw_v = data["vertices"]
    if not isinstance(raw_v, dict):
        raise _fail("vertices is an object {\"b\": [x, y], ...}", file, "vertices")
    if len(raw_v) > MAX_VERTICES:
        raise _fail(f"at most {MAX_VERTICES} vertices, got {len(raw_v)}", file, "vertices")
    vertices = {}
    for key, xy in raw_v.items():
        name = _name(key, file, f"vertices.{str(key)[:20]}")
        if not isinstance(xy, list) or len(xy) != 2:
            raise _fail(f"a vertex is [x, y] in mm, got {show(xy)}", file, f"vertices.{name}")
        x = _coord(xy[0], file, f"vertices.{name}[0]")
        y = _coord(xy[1], file, f"vertices.{name}[1]")
        if name in vertices:
            raise _fail(f"vertex {name!r} is given twice", file, f"vertices.{name}")
        vertices[name] = (x, -y if flip == "down" else y)
    raw_e = data["vectors"]
    if not isinstance(raw_e, list):
        raise _fail("vectors is a list of [from, to] pairs", file, "vectors")
    if len(raw_e) > MAX_VECTORS:
        raise _fail(f"at most {MAX_VECTORS} vectors, got {len(raw_e)}", file, "vectors")
    vectors = []
    for i, pair in enumerate(raw_e):
        if not isinstance(pair, list) or len(pair) != 2:
            raise _fail(f"a vector is [from, to], got {show(pair)}", file, f"vectors[{i}]")
        vectors.append((_name(pair[0], file, f"vectors[{i}]"),
                        _name(pair[1], file, f"vectors[{i}]")))
    return _build(data["diagram"], data["scale"], vertices, vectors, file)


def parse_svg(text: str, file: str = "<drawing>") -> StudentDrawing:
    import xml.etree.ElementTree as ET
    if re.search(r"<!(DOCTYPE|ENTITY)", text, re.IGNORECASE):
        raise _fail("an SVG drawing may not carry a DOCTYPE or entities", file)
    try:
        root = ET.fromstring(text)
    except (ET.ParseError, RecursionError) as exc:
        raise _fail(f"not valid SVG/XML: {' '.join(str(exc).split())[:100]}", file) from None
    diagram = root.get("data-polygons-drawing")
    if diagram is None:
        raise _fail("not a polygons drawing: the <svg> element has no "
                    "data-polygons-drawing=\"velocity\" (or \"acceleration\")", file)
    scale = root.get("data-scale")
    if scale is None:
        raise _fail("the <svg> element has no data-scale=\"1 mm = 0.02 m/s\"", file)
    vertices: dict = {}
    vectors = []
    for el in root.iter():
        if len(vertices) > MAX_VERTICES or len(vectors) > MAX_VECTORS:
            break
        name = el.get("data-vertex")
        if name is not None:
            n = _name(name, file, "data-vertex")
            xy = []
            for attr in ("cx", "cy"):
                try:
                    xy.append(_coord(float(el.get(attr, "")), file, f"{n}.{attr}"))
                except ValueError:
                    raise _fail(f"vertex {n!r} needs numeric cx and cy (mm)", file,
                                n) from None
            if n in vertices:
                raise _fail(f"vertex {n!r} is given twice", file, n)
            vertices[n] = (xy[0], -xy[1])
        a, b = el.get("data-from"), el.get("data-to")
        if a is not None or b is not None:
            vectors.append((_name(a, file, "data-from"), _name(b, file, "data-to")))
    try:
        num = float(scale)
    except ValueError:
        num = None
    return _build(diagram, num if num is not None else scale, vertices, vectors, file)


def to_json(drawing: StudentDrawing, scale_text: str | None = None) -> str:
    """The drawing as the JSON above (y up): what tests and the page write."""
    return json.dumps({"diagram": drawing.diagram,
                       "scale": scale_text or drawing.scale_text,
                       "vertices": {k: [round(v[0], 4), round(v[1], 4)]
                                    for k, v in drawing.vertices.items()},
                       "vectors": [list(p) for p in drawing.vectors]}, indent=1)


__all__ = ["StudentDrawing", "DrawingError", "read_drawing", "parse_json", "parse_svg",
           "to_json", "MAX_VERTICES", "MAX_VECTORS"]
