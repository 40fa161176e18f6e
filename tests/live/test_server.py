"""The transports, tested like a server: standard input to JSON lines; a WebSocket server on the
loopback address with an ephemeral port (a client streams and gets frames, a client vanishes
mid-stream, a client sends garbage, a client reads too slowly); clean shutdown on signals. Every
test binds only to 127.0.0.1 and ends by itself within seconds."""

import asyncio
import json
import os
import selectors
import signal
import socket
import subprocess
import sys
import time
import wave
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.live.server import StreamServer
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.model.motiondb import MotionDatabase

websockets = pytest.importorskip("websockets", reason="the WebSocket transport needs the websockets package")
from websockets.asyncio.client import connect  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def wav(tiny_corpus, held_out_take) -> Path:
    return tiny_corpus / "audio" / f"{held_out_take}.wav"


@pytest.fixture(scope="module")
def pcm(wav) -> bytes:
    with wave.open(str(wav)) as w:
        assert (w.getframerate(), w.getnchannels(), w.getsampwidth()) == (16000, 1, 2)
        return w.readframes(w.getnframes())


@pytest.fixture(scope="module")
def model(tiny_db, config):
    return LiveModel(MotionDatabase.read(tiny_db), config.settings("synthesize"), config.settings("stream"),
                     config.settings("solve"))


def _check_frames(messages: list[dict]):
    assert messages[0]["type"] == "hello" and len(messages[0]["arkit_names"]) == 52
    frames = [m for m in messages if m["type"] == "frame"]
    assert [f["index"] for f in frames] == list(range(len(frames)))
    assert messages[-1] == {"type": "end", "frames": len(frames)}
    jaw = np.array([f["arkit"][messages[0]["arkit_names"].index("jawOpen")] for f in frames])
    assert jaw.max() > 0.1 and jaw.min() < 0.5 * jaw.max()  # the mouth opens on vowels and closes
    return frames


def test_stdin_wav_to_json_lines(tiny_db, wav):
    result = CliRunner().invoke(main, ["stream", str(tiny_db)], input=wav.read_bytes())
    assert result.exit_code == 0, result.output
    frames = _check_frames([json.loads(line) for line in result.stdout.splitlines()])
    assert len(frames) == 70  # 2.32 s at 30 frames/s, as batch synthesis gives


def test_stdin_raw_pcm_with_markers(tiny_db, pcm):
    result = CliRunner().invoke(main, ["stream", str(tiny_db), "--markers", "--method", "greedy"], input=pcm)
    assert result.exit_code == 0, result.output
    frames = _check_frames([json.loads(line) for line in result.stdout.splitlines()])
    assert len(frames[0]["markers"]) == 91 * 3


def test_live_link_packets_follow_the_frames_and_realtime_paces_the_reading(tiny_db, pcm):
    from facesynth.domain.live.livelink import decode

    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as receiver:
        receiver.bind(("127.0.0.1", 0))
        receiver.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 20)
        receiver.settimeout(5)
        clip = pcm[: 16000]  # 0.5 s
        t0 = time.monotonic()
        result = CliRunner().invoke(main, ["stream", str(tiny_db), "--realtime", "--livelink",
                                           f"127.0.0.1:{receiver.getsockname()[1]}"], input=clip)
        took = time.monotonic() - t0
        assert result.exit_code == 0, result.output
        frames = [json.loads(line) for line in result.stdout.splitlines() if '"frame"' in line]
        packets = [decode(receiver.recvfrom(2048)[0]) for _ in frames]
    assert took >= 0.5  # read no faster than the audio plays
    assert [p.frame for p in packets] == [f["index"] for f in frames] and len(frames) == 15
    names = json.loads(result.stdout.splitlines()[0])["arkit_names"]
    jaw = names.index("jawOpen")
    np.testing.assert_allclose([p.values[17] for p in packets], [f["arkit"][jaw] for f in frames], atol=1e-4)


def test_stdin_wav_at_another_rate_is_refused(tiny_db, tmp_path):
    """On standard input the live format is required; the same file given with --audio is
    resampled (tests/live/test_stream_audio_files.py)."""
    path = tmp_path / "a.wav"
    with wave.open(str(path), "wb") as w:
        w.setnchannels(1), w.setsampwidth(2), w.setframerate(44100)
        w.writeframes(b"\0\0" * 4410)
    result = CliRunner().invoke(main, ["stream", str(tiny_db)], input=path.read_bytes())
    assert result.exit_code == 1 and result.stdout == ""
    assert ("standard input: the WAV is 44100 Hz, 1 channel(s), 16-bit; live input is 16000 Hz mono 16-bit (give the "
            "file with --audio FILE, which converts any sound file,") in result.output


async def _stream(port: int, pcm: bytes, chunk: int = 3200, before=()) -> list[dict]:
    async with connect(f"ws://127.0.0.1:{port}") as ws:
        for message in before:
            await ws.send(message)
        for a in range(0, len(pcm), chunk):
            await ws.send(pcm[a : a + chunk])
        await ws.send(json.dumps({"type": "end"}))
        out = []
        while not out or out[-1]["type"] != "end":
            out.append(json.loads(await asyncio.wait_for(ws.recv(), 20)))
        return out


def _serve(model, test, **options):
    """Run ``test(server)`` against a server on 127.0.0.1 (a free port), then stop it."""
    async def body():
        server = StreamServer(model, _align(), "127.0.0.1", 0, **options)
        await server.start()
        try:
            return await asyncio.wait_for(test(server), 60)
        finally:
            await server.stop()
    return asyncio.run(body())


def _align():
    from facesynth.base.config import Config

    return Config.load().settings("align")


def test_websocket_client_streams_and_gets_frames(model, pcm):
    messages = _serve(model, lambda server: _stream(server.port, pcm))
    assert len(_check_frames(messages)) == 70


def test_given_phone_timings_and_an_emotion_switch(model, pcm, tiny_corpus, held_out_take):
    from facesynth.domain.speech.utterance import read_utterance

    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    phones = [{"phone": p, "start": a, "end": b} for p, a, b in zip(utt.phones, utt.starts, utt.ends)]
    before = [json.dumps({"type": "start", "phones": "given", "emotion": "sad"}),
              json.dumps({"type": "phones", "phones": phones[:5]}), json.dumps({"type": "emotion", "name": "happy"}),
              json.dumps({"type": "phones", "phones": phones[5:]})]
    messages = _serve(model, lambda server: _stream(server.port, pcm, before=before))
    assert len(_check_frames(messages)) == 70


def test_a_client_that_vanishes_mid_stream_leaves_the_server_serving(model, pcm):
    async def test(server):
        async with connect(f"ws://127.0.0.1:{server.port}") as ws:
            await ws.send(pcm[: len(pcm) // 2])
            await ws.recv()  # hello
        # abruptly: a raw TCP connection that starts a handshake and drops
        with socket.create_connection(("127.0.0.1", server.port)) as raw:
            raw.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n")
        return await _stream(server.port, pcm)

    assert len(_check_frames(_serve(model, test))) == 70


def test_garbage_gets_an_error_and_the_stream_goes_on(model, pcm):
    async def test(server):
        async with connect(f"ws://127.0.0.1:{server.port}") as ws:
            assert json.loads(await ws.recv())["type"] == "hello"
            errors = []
            for junk in ("not json", "[1, 2]", json.dumps({"type": "dance"}), json.dumps({"type": "emotion", "name": 3}),
                         json.dumps({"type": "phones", "phones": []})):
                await ws.send(junk)
                errors.append(json.loads(await asyncio.wait_for(ws.recv(), 10)))
            await ws.send(b"\x01")  # an odd byte: kept for the next chunk, no harm
        return errors

    errors = _serve(model, test)
    assert [e["type"] for e in errors] == ["error"] * 5
    assert "must be a JSON object" in errors[0]["message"]
    assert "unknown message type 'dance'" in errors[2]["message"]
    assert "emotion '3' is not in the motion database" in errors[3]["message"]
    assert "phone timings need" in errors[4]["message"]


def test_oversized_messages_close_the_connection(model, config):
    small = LiveModel(model.db, config.settings("synthesize"), replace(model.stream, max_message_bytes=4096),
                      config.settings("solve"))

    async def test(server):
        async with connect(f"ws://127.0.0.1:{server.port}", max_size=None) as ws:
            await ws.recv()
            await ws.send(b"\0" * 10000)
            with pytest.raises(websockets.exceptions.ConnectionClosed):
                while True:
                    await asyncio.wait_for(ws.recv(), 10)
            return ws.close_code

    assert _serve(small, test) == 1009


def test_a_client_that_reads_too_slowly_is_disconnected_with_bounded_memory(model, pcm, config):
    slow = LiveModel(model.db, config.settings("synthesize"), replace(model.stream, queue_messages=8),
                     config.settings("solve"))

    async def test(server):
        sock = socket.socket()
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        sock.connect(("127.0.0.1", server.port))
        ws = await connect(f"ws://127.0.0.1:{server.port}", sock=sock, max_queue=1, close_timeout=1)
        try:
            await ws.send(json.dumps({"type": "start", "markers": True}))
            for _ in range(12):  # 28 s of audio, never reading a frame
                await ws.send(pcm)
                if not server.connections:
                    break
            for _ in range(100):
                if not server.connections:
                    break
                await asyncio.sleep(0.1)
            return server.connections, server.most_queued
        finally:
            ws.transport.abort()

    left, most = _serve(slow, test, socket_send_buffer=4096)
    assert not left  # the server let the slow client go
    assert most <= 8  # and never held more than its bound for it


@pytest.mark.parametrize("sig,workers", [(signal.SIGTERM, 1), (signal.SIGINT, 1), (signal.SIGTERM, 2)])
def test_a_signal_stops_the_server_cleanly(tiny_db, sig, workers):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    proc = subprocess.Popen([sys.executable, "-m", "facesynth.cli", "stream", str(tiny_db), "--serve", "127.0.0.1:0",
                             "--workers", str(workers)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    try:
        line = _read_line(proc, 60)
        assert line.startswith("listening on ws://127.0.0.1:"), line
        port = int(line.split()[2].rsplit(":", 1)[1])

        async def client():
            # several clients: with two workers the kernel spreads them over both processes
            sockets = [await connect(f"ws://127.0.0.1:{port}") for _ in range(2 * workers)]
            for ws in sockets:
                assert json.loads(await ws.recv())["type"] == "hello"
            await asyncio.sleep(0.2)
            proc.send_signal(sig)
            codes = []
            for ws in sockets:
                with pytest.raises(websockets.exceptions.ConnectionClosed):
                    await asyncio.wait_for(ws.recv(), 15)
                codes.append(ws.close_code)
            return codes

        assert asyncio.run(client()) == [1001] * (2 * workers)  # going away
        assert proc.wait(15) == 0
        assert "stopped." in proc.stderr.read().decode()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def _read_line(proc, timeout: float) -> str:
    with selectors.DefaultSelector() as sel:
        sel.register(proc.stderr, selectors.EVENT_READ)
        if not sel.select(timeout):
            raise AssertionError("the server did not start")
    return proc.stderr.readline().decode().strip()


@pytest.mark.parametrize("args,message", [
    (["--serve", "8765"], "--serve '8765': give HOST:PORT, e.g. 127.0.0.1:8765."),
    (["--lookahead", "-1"], "--lookahead -1: give 0 or more phones."),
    (["--audio", "missing.wav"], "missing.wav: no such audio file."),
])
def test_bad_stream_options_say_what_to_do(tiny_db, args, message):
    result = CliRunner().invoke(main, ["stream", str(tiny_db), *args], input=b"")
    assert result.exit_code == 1 and message in result.output, result.output


def test_start_after_audio_is_refused(model):
    from facesynth.base.errors import InputError
    from facesynth.domain.live.session import Session

    session = Session(model, _align(), "client 1")
    session.audio(b"\0\0" * 320)
    with pytest.raises(InputError, match="client 1: 'start' must come before any audio or phones."):
        session.control(json.dumps({"type": "start", "phones": "given"}))
    assert session.end()[-1]["type"] == "end" and session.end() == []
    with pytest.raises(InputError, match="client 1: audio after 'end'; open a new stream"):
        session.audio(b"\0\0")


def test_a_start_message_in_another_language_takes_ipa_phones(model):
    from facesynth.base.errors import InputError
    from facesynth.domain.live.session import Session

    french = Session(model, _align(), "client 1")
    french.control(json.dumps({"type": "start", "phones": "given", "language": "fr-CA"}))
    french.control(json.dumps({"type": "phones", "phones": [{"phone": "b", "start": 0.1, "end": 0.2},
                                                             {"phone": "y", "start": 0.2, "end": 0.3}]}))
    assert french.synth.phones[-2:] == ["b", "uw"]  # French /y/: the rounded vowel, not the glide
    english = Session(model, _align(), "client 2")
    english.control(json.dumps({"type": "start", "phones": "given", "language": "en"}))
    english.control(json.dumps({"type": "phones", "phones": [{"phone": "y", "start": 0.1, "end": 0.2}]}))
    assert english.synth.phones[-1] == "y"
    with pytest.raises(InputError, match="client 3: 'language' of 'start' must be a BCP-47 tag like en, de, fr or "
                                         "cmn, not 'French!'."):
        Session(model, _align(), "client 3").control(json.dumps({"type": "start", "language": "French!"}))


@pytest.mark.parametrize("pause_wait_s", [0.1, 0.25])
def test_given_phones_at_their_start_leave_no_frame_waiting_past_the_pause_wait(tiny_db, config, pcm, tiny_corpus,
                                                                                held_out_take, pause_wait_s):
    """A TTS engine sends each phone as it starts speaking it (look-ahead 0): the silences between
    its phones are taken as pauses after stream.pause_wait_s, and their frames go out then."""
    from facesynth.domain.live.session import Session
    from facesynth.domain.speech.utterance import read_utterance

    stream = replace(config.settings("stream"), lookahead_phones=0, pause_wait_s=pause_wait_s)
    model = LiveModel(MotionDatabase.read(tiny_db), config.settings("synthesize"), stream, config.settings("solve"))
    utt = read_utterance(tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    spoken = [{"phone": p, "start": float(a), "end": float(b)} for p, a, b in zip(utt.phones, utt.starts, utt.ends)
              if p != "pau"]  # the engine names no pauses: the gaps between its phones are the silences
    session = Session(model, _align(), "engine")
    session.control(json.dumps({"type": "start", "phones": "given"}))
    step, sent_at, pending = 640, {}, list(spoken)
    for c in range(0, len(pcm), step):
        now = (c + step) / 32000
        starting = [p for p in pending if p["start"] < now]
        pending = pending[len(starting):]
        out = session.control(json.dumps({"type": "phones", "phones": starting})) if starting else []
        out += session.audio(pcm[c : c + step])
        sent_at.update({m["index"]: (m["time"], session.time) for m in out if m["type"] == "frame"})
    end = session.end()
    assert end[-1]["type"] == "end" and end[-1]["frames"] == len(sent_at) + sum(m["type"] == "frame" for m in end)
    assert session.synth.phones == list(utt.phones)  # the pauses found are the text's
    frame = 1 / stream.fps
    late = [(i, t, at) for i, (t, at) in sent_at.items() if at - t > pause_wait_s + 0.02 + 2 * frame]
    # speech frames wait for the next phone only by the join smoothing's reach; pauses by the wait
    reach = config.settings("synthesize").smoothing_half_window / model.db.fps
    assert all(at - t <= max(pause_wait_s, reach) + 0.02 + 2 * frame for _, t, at in late), late[:5]
    # only the frames of the last pause_wait_s of audio wait for the end of the stream
    assert sum(m["type"] == "frame" for m in end) <= np.ceil(pause_wait_s * stream.fps) + 2
