"""Exit statuses as docs/pipeline.md documents them (0 ok, 1 bad input or data, 2 bad usage, 130
interrupted), and the ordinary mistakes that used to end in a traceback or do nothing: each
through click's CliRunner, checking the status, the message and that nothing was written."""

import numpy as np
import pytest
import soundfile as sf
from click.testing import CliRunner

from facesynth.base.config import SECTIONS
from facesynth.base.errors import InputError
from facesynth.cli import READS, main
from facesynth.domain.rendering import video
from facesynth.formats.labels import read_phone_segments


def _run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def _is_error(result, status: int, *phrases: str) -> None:
    """``result`` ended with ``status``, no traceback, and an error naming each of ``phrases``."""
    assert result.exit_code == status, result.output
    assert isinstance(result.exception, SystemExit), result.exception  # not an escaped exception
    assert "Traceback" not in result.output
    error_lines = [line for line in result.output.splitlines() if line.startswith(("error: ", "Error: "))]
    assert len(error_lines) == 1, result.output
    for phrase in phrases:
        assert phrase in error_lines[0], result.output


@pytest.fixture(scope="module")
def utterance(tiny_corpus, held_out_take):
    """The held-out take's TextGrid and its duration (s)."""
    path = tiny_corpus / "labels" / f"{held_out_take}.TextGrid"
    return path, read_phone_segments(path, ("phones",))[-1].end


@pytest.fixture(scope="module")
def anim(tiny_db, tiny_corpus, held_out_take, utterance, tmp_path_factory):
    """A mesh animation of the held-out take and that take's own audio."""
    d = tmp_path_factory.mktemp("exit_codes")
    assert _run("synthesize", tiny_db, "--phonemes", utterance[0], "-o", d / "m.h5", "-q").exit_code == 0
    assert _run("deform", d / "m.h5", "--mesh", tiny_corpus / "face.obj", "--binding", tiny_corpus / "markers.csv",
                "-o", d / "a.h5", "-q").exit_code == 0
    return d / "a.h5", tiny_corpus / "audio" / f"{held_out_take}.wav"


# --- one test per exit-status class -------------------------------------------------------

def test_exit_0_ok(tiny_artifacts, tmp_path):
    r = _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "-q")
    assert r.exit_code == 0, r.output
    assert (tmp_path / "p.h5").exists()


def test_exit_1_bad_input(tiny_artifacts, tmp_path):
    _is_error(_run("pca", tiny_artifacts["corpus"], "-o", tmp_path / "p.h5"), 1, "expected 'normalized'")
    assert not (tmp_path / "p.h5").exists()


def test_exit_2_bad_usage(tiny_artifacts, tmp_path):
    _is_error(_run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "--set", "alpha1=3"), 2,
              "--set 'alpha1=3': expected section.key=value")
    assert not (tmp_path / "p.h5").exists()


def test_exit_130_on_ctrl_c(tiny_artifacts, tmp_path, monkeypatch):
    from facesynth.stages import pca

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(pca, "run", interrupted)
    r = _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5")
    assert r.exit_code == 130, r.output
    assert "interrupted; no output was written." in r.output and "Traceback" not in r.output


# --- bad usage: missing or contradictory options, bad --set (were exit 1 or ignored) ------

def test_synthesize_without_phones_is_usage(tiny_db, tmp_path):
    _is_error(_run("synthesize", tiny_db, "-o", tmp_path / "m.h5"), 2, "give the utterance's phones with --phonemes")
    assert not (tmp_path / "m.h5").exists()


def test_synthesize_phones_twice_is_usage(tiny_db, utterance, anim, tmp_path):
    _is_error(_run("synthesize", tiny_db, "--phonemes", utterance[0], "--audio", anim[1], "--text", "a b",
                   "-o", tmp_path / "m.h5"), 2, "leave out --text")
    assert not (tmp_path / "m.h5").exists()


def test_render_needs_one_audio_per_animation(anim, tmp_path):
    _is_error(_run("render", anim[0], anim[0], "--audio", anim[1], "-o", tmp_path / "v.avi"), 2,
              "give one --audio per animation (2 animations, 1 audio files)")
    assert not (tmp_path / "v.avi").exists()


def test_align_text_and_transcript_is_usage(anim, tmp_path):
    transcript = tmp_path / "t.txt"
    transcript.write_text("hello\n")
    _is_error(_run("align", anim[1], "--text", "hello", "--transcript", transcript, "-o", tmp_path / "a.TextGrid"), 2,
              "give one of --text or --transcript, not both")


def test_prune_remove_and_auto_is_usage(tiny_db, tmp_path):
    _is_error(_run("prune", tiny_db, "--remove", "1", "--auto", "-o", tmp_path / "p.h5"), 2,
              "give exactly one of --remove IDS or --auto")


def test_greedy_with_constraints_is_usage(tiny_db, utterance, tmp_path):
    constraints = tmp_path / "c.txt"
    constraints.write_text("1 0\n")
    _is_error(_run("synthesize", tiny_db, "--phonemes", utterance[0], "--constraints", constraints,
                   "--search", "greedy", "-o", tmp_path / "m.h5"), 2, "need the DP search")


@pytest.mark.parametrize("override, phrase", [
    ("pca.n_components=0", "'pca.n_components' must be an integer >= 1"),
    ("pca.n_componentz=3", "unknown key 'pca.n_componentz'"),
    ("bogus.x=1", "unknown section [bogus]"),
])
def test_bad_set_value_is_usage(tiny_artifacts, tmp_path, override, phrase):
    _is_error(_run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "--set", override), 2, phrase)


def test_bad_config_file_value_stays_bad_input(tiny_artifacts, tmp_path):
    config = tmp_path / "c.toml"
    config.write_text("[pca]\nn_components = 0\n")
    _is_error(_run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "--config", config), 1,
              "c.toml: 'pca.n_components' must be")


def test_set_for_a_section_the_command_does_not_read(tiny_db, utterance, tmp_path):
    r = _run("synthesize", tiny_db, "--phonemes", utterance[0], "-o", tmp_path / "m.h5", "--set", "deform.sigma=3")
    _is_error(r, 2, "--set deform.sigma=3: [deform] is read by facesynth deform, facesynth batch; facesynth synthesize reads "
                    "[synthesize], [ingest], [align], [trajectory], [coarticulation], so this setting would be ignored.")
    assert not (tmp_path / "m.h5").exists()
    r = _run("db", "show", tiny_db, "--set", "synthesize.alpha1=3")
    _is_error(r, 2, "is read by facesynth synthesize, facesynth suggest", "facesynth db show reads no settings")


def test_config_file_may_hold_other_sections(tiny_artifacts, tmp_path):
    config = tmp_path / "whole_pipeline.toml"
    config.write_text("[pca]\nn_components = 6\n[deform]\nsigma = 3.0\n")
    r = _run("pca", tiny_artifacts["normalized"], "-o", tmp_path / "p.h5", "--config", config, "-q")
    assert r.exit_code == 0, r.output


def test_reads_table_covers_every_command_and_section():
    def paths(group, prefix=""):
        for name, command in group.commands.items():
            if hasattr(command, "commands"):
                yield from paths(command, f"{prefix}{name} ")
            else:
                yield prefix + name

    assert sorted(paths(main)) == sorted(READS)
    assert {s for sections in READS.values() for s in sections} == set(SECTIONS)


# --- outputs: tracebacks before, one line and exit 1 now ----------------------------------

def test_evaluate_into_an_existing_file(tiny_db, tiny_artifacts, tmp_path):
    existing = tmp_path / "report.txt"
    existing.write_text("keep me\n")
    _is_error(_run("evaluate", tiny_db, "--heldout", tiny_artifacts["corpus"], "-o", existing), 1,
              "report.txt: is a file, but this output is a folder (for the report)")
    assert existing.read_text() == "keep me\n"


def test_evaluate_into_a_folder_that_is_not_empty(tiny_db, tiny_artifacts, tmp_path):
    (tmp_path / "notes.txt").write_text("mine\n")
    _is_error(_run("evaluate", tiny_db, "--heldout", tiny_artifacts["corpus"], "-o", tmp_path), 1,
              "is not empty; pass --overwrite")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt"]


@pytest.mark.parametrize("quiet", [(), ("-q",)])
def test_synthesize_into_a_folder(tiny_db, utterance, tmp_path, quiet):
    _is_error(_run("synthesize", tiny_db, "--phonemes", utterance[0], "-o", tmp_path, "--overwrite", *quiet), 1,
              "is a folder, but this output is one file")
    assert list(tmp_path.iterdir()) == []


def test_folder_outputs_that_are_files(tiny_db, tmp_path):
    existing = tmp_path / "taken"
    existing.write_text("keep me\n")
    _is_error(_run("isomap", tiny_db, "-o", tmp_path / "i.h5", "--images", existing), 1,
              "taken: is a file, but this output is a folder (for the images)")
    _is_error(_run("sample-corpus", existing, "--preset", "tiny"), 1, "taken: is a file")
    assert existing.read_text() == "keep me\n" and not (tmp_path / "i.h5").exists()


# --- no silent no-ops ---------------------------------------------------------------------

def test_emotion_span_outside_the_utterance(tiny_db, utterance, tmp_path):
    spans = tmp_path / "spans.txt"
    spans.write_text("# in seconds\n100 200 happy\n")
    r = _run("synthesize", tiny_db, "--phonemes", utterance[0], "--emotions", spans, "-o", tmp_path / "m.h5")
    _is_error(r, 1, "spans.txt, line 2: the emotion span 100 to 200 s lies outside the utterance",
              f"to {utterance[1]:.3f} s)")
    assert not (tmp_path / "m.h5").exists()


def test_emotion_span_partly_outside_is_fine(tiny_db, utterance, tmp_path):
    spans = tmp_path / "spans.txt"
    spans.write_text("0 1000 happy\n")
    r = _run("synthesize", tiny_db, "--phonemes", utterance[0], "--emotions", spans, "-o", tmp_path / "m.h5")
    assert r.exit_code == 0, r.output
    assert "emotion span" not in r.output


def test_emotion_span_between_midpoints_is_warned_about(tiny_db, utterance, tmp_path):
    from facesynth.domain.speech.utterance import read_utterance

    utt = read_utterance(utterance[0], ("phones",))
    spans = tmp_path / "spans.txt"
    spans.write_text(f"{utt.starts[1]:.4f} {utt.starts[1] + 0.001:.4f} happy\n")
    r = _run("synthesize", tiny_db, "--phonemes", utterance[0], "--emotions", spans, "-o", tmp_path / "m.h5")
    assert r.exit_code == 0, r.output
    assert "warning: " in r.output and "holds no phone's midpoint, so it changes nothing" in r.output


def test_constraint_outside_the_utterance(tiny_db, utterance, tmp_path):
    constraints = tmp_path / "c.txt"
    constraints.write_text("100s 0\n")
    _is_error(_run("synthesize", tiny_db, "--phonemes", utterance[0], "--constraints", constraints,
                   "-o", tmp_path / "m.h5"), 1, "c.txt, line 1: time 100.000 s is outside the utterance")


@pytest.mark.parametrize("extra_s", [1.2, -0.2])
def test_render_refuses_audio_of_another_length(anim, tmp_path, extra_s):
    x, rate = sf.read(anim[1])
    n = len(x) + int(extra_s * rate)
    other = tmp_path / "other.wav"
    sf.write(other, np.pad(x, (0, max(0, n - len(x))))[:n], rate)
    _is_error(_run("render", anim[0], "--audio", other, "-o", tmp_path / "v.avi"), 1,
              "other.wav: the audio lasts", "more than 2 frames apart")
    assert not (tmp_path / "v.avi").exists()


def test_render_takes_audio_within_two_frames(tmp_path):
    n_frames, rate = 90, 16000
    for frames_off in (-1.9, 1.9):
        sf.write(tmp_path / "a.wav", np.zeros(int(round((n_frames + frames_off) / 30.0 * rate))), rate)
        assert len(video.clip_audio(tmp_path / "a.wav", n_frames, 30.0, 48000)) == n_frames / 30.0 * 48000
    sf.write(tmp_path / "a.wav", np.zeros(int(round((n_frames + 2.5) / 30.0 * rate))), rate)
    with pytest.raises(InputError, match="more than 2 frames apart"):
        video.clip_audio(tmp_path / "a.wav", n_frames, 30.0, 48000)
