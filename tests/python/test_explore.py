"""gridifs.random and gridifs.mutate: the explore verbs' draws from Python."""
import json

import pytest

from conftest import asset, gridifs, run_cli


def test_random_is_the_verbs_world_for_the_same_seed(tmp):
    out = tmp / "w.gridifs"
    code, err = run_cli("random", "-o", out, "--seed", 21, "--style", "flame")
    assert code == 0, err
    p = gridifs.random(style="flame", seed=21)
    assert p.to_json() == out.read_text()
    assert json.loads(p.to_json())["lineage"]["seed"] == 21
    assert p.render(width=48, height=36, samples=50000).any()


def test_mutate_keeps_what_it_is_told_and_records_its_parents():
    parent = gridifs.Project.load(asset("twisted_functions.gridifs"))
    child = gridifs.mutate(parent, seed=4, strength=1.0, keep=["ops", "camera"])
    a, b = json.loads(parent.to_json()), json.loads(child.to_json())
    assert a["camera"] == b["camera"]
    assert [f["ops"] for f in a["functions"]] == [f["ops"] for f in b["functions"]]
    assert b["lineage"]["parents"] == [parent.source]
    assert a != {k: v for k, v in b.items() if k != "lineage"}
    mate = gridifs.Project.load(asset("tapered_functions.gridifs"))
    bred = gridifs.mutate(parent, mate=mate, seed=1, strength=0.2)
    assert len(json.loads(bred.to_json())["lineage"]["parents"]) == 2


@pytest.mark.parametrize(
    "call,words",
    [
        (lambda: gridifs.random(style="fuzzy"), "style must be"),
        (lambda: gridifs.random(functions=99), "functions must be between"),
        (lambda: gridifs.mutate(gridifs.Project(), strength=0), "strength must be"),
        (lambda: gridifs.mutate(gridifs.Project(), keep=["colours"]), 'not "colours"'),
    ],
)
def test_bad_explore_options_are_errors(call, words):
    with pytest.raises(gridifs.Error) as refused:
        call()
    assert words in str(refused.value)
