import pytest

from facesynth.base.errors import InputError
from facesynth.domain.batch.script import read_script


def test_lines_resolve_paths_against_the_script_folder(tmp_path):
    script = tmp_path / "script.csv"
    script.write_text("ID,Audio,Text,Emotion,extra\nl1,a/x.wav,hello there,happy,1\n\nl2,y.wav,hi,,\n")
    lines = read_script(script)
    assert [(l.id, l.row, l.audio, l.text, l.emotion) for l in lines] == [
        ("l1", 2, tmp_path / "a" / "x.wav", "hello there", "happy"), ("l2", 4, tmp_path / "y.wav", "hi", None)]
    assert all(l.problem is None and l.alignment is None for l in lines)


@pytest.mark.parametrize("header, missing", [("audio,text", "id"), ("id,text", "audio"), ("text,emotion", "id, audio")])
def test_a_script_without_the_required_columns_is_refused(tmp_path, header, missing):
    script = tmp_path / "s.csv"
    script.write_text(header + "\nx,y,z\n")
    with pytest.raises(InputError, match=rf"s.csv: the header lacks the column\(s\) {missing.replace('(', '.').replace(')', '.')};"):
        read_script(script)


def test_a_script_without_text_or_alignment_gives_lines_to_recognise(tmp_path):
    script = tmp_path / "s.csv"
    script.write_text("id,audio,emotion\nl1,x.wav,sad\n")
    [line] = read_script(script)
    assert (line.id, line.audio, line.text, line.alignment, line.emotion, line.problem) == \
        ("l1", tmp_path / "x.wav", None, None, "sad", None)


def test_empty_and_header_only_scripts_are_refused(tmp_path):
    empty, header = tmp_path / "e.csv", tmp_path / "h.csv"
    empty.write_text("")
    header.write_text("id,audio,text\n")
    with pytest.raises(InputError, match="e.csv: the script is empty"):
        read_script(empty)
    with pytest.raises(InputError, match="h.csv: the script has a header but no lines"):
        read_script(header)
    with pytest.raises(InputError, match="script not found"):
        read_script(tmp_path / "none.csv")


def test_duplicated_and_unusable_ids_fail_only_their_line(tmp_path):
    script = tmp_path / "s.csv"
    script.write_text("id,audio,alignment\na,x.wav,x.TextGrid\na,y.wav,y.TextGrid\n../up,z.wav,z.lab\n,w.wav,w.lab\n")
    lines = read_script(script)
    assert [l.problem is None for l in lines] == [True, False, False, False]
    assert "id 'a' is already used by row 2" in lines[1].problem
    assert "id '../up' is not usable as a file name" in lines[2].problem and lines[3].id == "row5"
