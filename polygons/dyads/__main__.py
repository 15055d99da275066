"""``python -m polygons.dyads``: write the kinds' static index (``_index.py``) from discovery."""
from pathlib import Path

from . import index_source

Path(__file__).with_name("_index.py").write_text(index_source(), encoding="utf-8")
