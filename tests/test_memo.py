"""polygons.memo: a memo lives with its record and dies with it, even when it refers back."""
import copy
import gc
import weakref
from dataclasses import dataclass, replace

from polygons.memo import memo_of


@dataclass(frozen=True)
class Record:
    name: str


def test_a_memo_that_refers_back_is_collected_with_its_record():
    rec = Record("a")
    memo_of(rec)["plan"] = ("plan of", rec)      # the cycle a scene's plan makes
    dead = weakref.ref(rec)
    del rec
    gc.collect()
    assert dead() is None


def test_a_memo_is_not_a_field_and_is_not_shared_by_copies():
    rec = Record("a")
    memo_of(rec)["x"] = 1
    assert memo_of(rec) == {"x": 1}
    assert rec == Record("a") and repr(rec) == "Record(name='a')"
    assert memo_of(replace(rec)) == {} and memo_of(copy.copy(rec)) == {}
    assert memo_of(rec) == {"x": 1}


def test_solving_many_scenes_keeps_none_of_them(tmp_path):
    """Each solved scene (its plan, program and memo) is collected once dropped."""
    from pathlib import Path
    from polygons.scene import load_scene
    from polygons.evaluate import solve
    case = Path(__file__).resolve().parents[1] / "cases" / "s003-fig7.toml"
    refs = []
    for _ in range(3):
        scene = load_scene(str(case))
        solve(scene)
        refs.append(weakref.ref(scene))
        del scene
    gc.collect()
    assert [r() for r in refs] == [None, None, None]
