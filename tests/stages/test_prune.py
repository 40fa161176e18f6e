import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.errors import InputError
from facesynth.cli import main
from facesynth.domain.database.contamination import excursions
from facesynth.model.motiondb import Nodes
from facesynth.stages import prune
from facesynth.stages.prune import parse_ids


def test_excursion_of_a_spike_and_a_swap():
    t = np.linspace(0, 1, 200)
    track = np.stack([np.sin(3 * t), np.cos(2 * t), t], 1) * 5.0  # smooth motion, small steps
    spiked = track.copy()
    spiked[50:53] += [20.0, 0.0, 0.0]
    assert excursions(spiked, threshold=2.0, max_len=120) == [(50, 53)]
    # a jump that never returns (e.g. a marker relabelled to the end) flags just its frame
    jumped = track.copy()
    jumped[150:] += [0.0, 15.0, 0.0]
    assert excursions(jumped, threshold=2.0, max_len=120) == [(150, 151)]
    assert excursions(track, threshold=2.0, max_len=120) == []


def test_parse_ids():
    assert parse_ids("3, 5,10-12", 20) == [3, 5, 10, 11, 12]
    with pytest.raises(InputError, match=r"node\(s\) \[25\] do not exist; the database has nodes 0 to 19"):
        parse_ids("1,25", 20)
    with pytest.raises(InputError, match="is not a node id or a range"):
        parse_ids("a", 20)


def test_removing_nodes_keeps_links_and_costs_consistent(tiny_db, tmp_path, config):
    out = tmp_path / "clean.h5"
    before = tiny_db.read_bytes()
    with h5py.File(tiny_db) as f:
        nodes = Nodes.read(f)
        first_pos = f["boundary/first_pos"][()]
        dsc_in = f["transition/dsc_in"][()]
    victim = int(np.nonzero((nodes.pre >= 0) & (nodes.suc >= 0))[0][0])  # a node inside a captured run
    s = prune.run(tiny_db, out, config.settings("prune"), str(victim), False, "test", False)
    assert s == prune.PruneResult(removed=1, kept=len(nodes) - 1, links_cut=1, found={victim: "test"})
    assert tiny_db.read_bytes() == before  # the input is never changed
    with h5py.File(out) as f:
        kept = Nodes.read(f)
        original = f["pruned/original_id"][()]
        assert f["pruned/removed_id"][()].tolist() == [victim]
        assert [r.decode() for r in f["pruned/reason"][()]] == ["test"]
        assert np.array_equal(f["boundary/first_pos"][()], first_pos[original])
        cut = original.tolist().index(nodes.suc[victim])
        assert not f["transition/dsc_in"][cut].any() and f["transition/dsc_scale"][cut] == 0.0  # rule 4: DSC unused
        others = np.array([k for k in range(len(original)) if k != cut])
        assert np.array_equal(f["transition/dsc_in"][()][others], dsc_in[original[others]])
    assert victim not in original.tolist() and len(kept) == len(nodes) - 1
    successor = original.tolist().index(nodes.suc[victim])
    predecessor = original.tolist().index(nodes.pre[victim])
    assert kept.pre[successor] == -1 and kept.suc[predecessor] == -1
    for k in range(len(kept)):
        if kept.pre[k] >= 0:
            assert kept.suc[kept.pre[k]] == k and original[kept.pre[k]] == nodes.pre[original[k]]


def test_auto_finds_the_injected_contamination(small_db_and_truth, config):
    from facesynth.domain.database.contamination import contaminated_nodes, detect
    from facesynth.model.artifacts import open_artifact, read
    from facesynth.model.tables import Takes

    db, truth_csv = small_db_and_truth
    with open_artifact(db, "motiondb") as f:
        nodes, takes = Nodes.read(f), Takes.read(f)
        found = detect(nodes, takes, read(f, "markers"), read(f, "coefficients"), 120.0, config.settings("prune"))
    truth = contaminated_nodes(nodes, takes, truth_csv)
    hits = len(set(found) & truth)
    assert len(truth) >= 10
    assert hits / len(found) >= 0.9 and hits / len(truth) >= 0.9


def test_db_show_lists_and_details(tiny_db):
    r = CliRunner().invoke(main, ["db", "show", str(tiny_db), "--phoneme", "ax"])
    assert r.exit_code == 0
    lines = r.output.strip().splitlines()
    assert lines[0].startswith("id\tphone\tcontext") and all("\tax\t" in line for line in lines[1:])
    r = CliRunner().invoke(main, ["db", "show", str(tiny_db), "--node", "5"])
    assert "captured predecessor" in r.output
    r = CliRunner().invoke(main, ["db", "show", str(tiny_db), "--node", "99999"])
    assert r.exit_code == 1 and "node 99999 does not exist" in r.output


def test_prune_needs_one_of_remove_or_auto(tiny_db, tmp_path):
    r = CliRunner().invoke(main, ["prune", str(tiny_db), "-o", str(tmp_path / "x.h5")])
    assert r.exit_code == 2 and "exactly one of --remove IDS or --auto" in r.output  # bad usage
