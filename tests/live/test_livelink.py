"""The Live Link Face UDP packet, checked against the protocol's layout with a parser written here
from the description (big-endian: uint8 version 6, two uint32-length-prefixed UTF-8 strings,
int32 frame, float32 sub-frame, int32 rate numerator and denominator, uint8 count 61, 61 float32)."""

import socket
import struct

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.live.livelink import LiveLinkSender, decode, encode, value_names
from facesynth.domain.rig.face import load_face_rig

#: Positions of some blendshapes in Unreal's EARFaceBlendShape (ARKit's ARFaceAnchor order).
ENUM_POSITIONS = {"EyeBlinkLeft": 0, "EyeWideRight": 13, "JawForward": 14, "JawLeft": 15, "JawRight": 16, "JawOpen": 17,
                  "MouthClose": 18, "MouthLeft": 21, "MouthRight": 22, "MouthPressRight": 36, "BrowInnerUp": 43,
                  "TongueOut": 51, "HeadYaw": 52, "RightEyeRoll": 60}


def parse(packet: bytes) -> dict:
    """The protocol's layout, read field by field."""
    out, at = {"version": packet[0]}, 1
    for name in ("device", "subject"):
        (n,) = struct.unpack_from(">I", packet, at)
        out[name] = packet[at + 4 : at + 4 + n].decode("utf-8")
        at += 4 + n
    out["frame"], out["subframe"], out["num"], out["den"] = struct.unpack_from(">ifii", packet, at)
    out["count"] = packet[at + 16]
    out["values"] = struct.unpack_from(">61f", packet, at + 17)
    out["size"] = at + 17 + 4 * 61
    return out


def test_packet_layout_and_round_trip():
    weights = np.linspace(0.0, 1.0, 52)
    packet = encode("0123456789abcdef0123456789abcdef0123", "facesynth", 1234, 60, weights, subframe=0.25)
    p = parse(packet)
    assert (p["version"], p["device"], p["subject"]) == (6, "0123456789abcdef0123456789abcdef0123", "facesynth")
    assert (p["frame"], p["subframe"], p["num"], p["den"], p["count"]) == (1234, 0.25, 60, 1, 61)
    assert len(packet) == p["size"] == 315  # the size the module docstring works out
    np.testing.assert_allclose(p["values"][:52], weights, atol=1e-7)
    assert p["values"][52:] == (0.0,) * 9
    d = decode(packet)
    assert (d.device_id, d.subject, d.frame, d.subframe, d.fps_numerator, d.fps_denominator) == \
        ("0123456789abcdef0123456789abcdef0123", "facesynth", 1234, 0.25, 60, 1)
    np.testing.assert_allclose(d.values[:52], weights, atol=1e-7)


def test_value_names_follow_the_enum():
    names = value_names()
    assert len(names) == 61
    assert {n: names.index(n) for n in ENUM_POSITIONS} == ENUM_POSITIONS


@pytest.mark.parametrize("cut,match", [(lambda p: p[:100], "ends inside a field"), (lambda p: b"\x05" + p[1:], "version 5"),
                                       (lambda p: p + b"\0", "1 bytes after the 61 values")])
def test_malformed_packets_are_refused(cut, match):
    packet = encode("d", "s", 0, 30, np.zeros(52))
    with pytest.raises(InputError, match=match):
        decode(cut(packet))


def test_sender_places_values_by_name_over_udp_on_loopback():
    rig = load_face_rig()
    names = rig.arkit_names
    weights = np.zeros(len(names))
    weights[names.index("jawOpen")] = 0.75
    weights[names.index("jawLeft")] = 0.25
    weights[names.index("mouthRight")] = 0.5
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as receiver:
        receiver.bind(("127.0.0.1", 0))
        receiver.settimeout(5)
        sender = LiveLinkSender("127.0.0.1", receiver.getsockname()[1], "facesynth", "dev", 30, names)
        try:
            sender.send(7, weights)
            packet, _ = receiver.recvfrom(2048)
        finally:
            sender.close()
    p = parse(packet)
    assert p["frame"] == 7 and p["num"] == 30
    values = dict(zip(value_names(), p["values"]))
    assert values["JawOpen"] == 0.75 and values["JawLeft"] == 0.25 and values["MouthRight"] == 0.5
    assert sum(v != 0 for v in values.values()) == 3
