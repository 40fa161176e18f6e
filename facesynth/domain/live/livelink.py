"""The Live Link Face UDP packet: what Epic's Live Link Face iPhone app sends to Unreal Engine's
Live Link plugin (Apple ARKit Face Support, ``AppleARKitLiveLinkSource.cpp``), default port
11111, one datagram per frame. Every multi-byte field is big-endian (network order):

=========  =====================  ==============================================================
bytes      field                  value
=========  =====================  ==============================================================
1          packet version         uint8, 6
4 + n      device id              uint32 length n, then n bytes UTF-8 (the app: a UUID)
4 + m      subject name           uint32 length m, then m bytes UTF-8 (the Live Link subject)
4          frame number           int32 (FQualifiedFrameTime's FFrameTime frame)
4          sub-frame              float32 in [0, 1)
4          frame rate numerator   int32 (e.g. 60)
4          frame rate denominator int32 (1)
1          blendshape count       uint8, 61
61 x 4     values                 float32: the 52 blendshapes in the order of Unreal's
                                  ``EARFaceBlendShape`` (:data:`PACKET_NAMES`), then HeadYaw,
                                  HeadPitch, HeadRoll, LeftEyeYaw, LeftEyePitch, LeftEyeRoll,
                                  RightEyeYaw, RightEyePitch, RightEyeRoll (radians)
=========  =====================  ==============================================================

The packet's order is not the app's CSV column order (:mod:`facesynth.formats.livelink_face`): the
enum has JawLeft before JawRight and MouthLeft before MouthRight, the CSV the other way round;
values are placed by name. With a 36-character device id and a 9-character subject the packet is
1 + 40 + 13 + 16 + 1 + 244 = 315 bytes. facesynth sends no head or eye rotation (zeros) in live
mode.
"""

from __future__ import annotations

import socket
import struct
from dataclasses import dataclass

import numpy as np

from facesynth.base.errors import InputError
from facesynth.formats.livelink_face import ROTATION_COLUMNS

#: Packet version of the Live Link Face app this layout is.
PACKET_VERSION = 6
#: Values per packet: 52 blendshapes and 9 rotations.
VALUE_COUNT = 61
#: The 52 blendshapes in packet order (Unreal's ``EARFaceBlendShape``).
PACKET_NAMES = (
    "EyeBlinkLeft", "EyeLookDownLeft", "EyeLookInLeft", "EyeLookOutLeft", "EyeLookUpLeft", "EyeSquintLeft",
    "EyeWideLeft", "EyeBlinkRight", "EyeLookDownRight", "EyeLookInRight", "EyeLookOutRight", "EyeLookUpRight",
    "EyeSquintRight", "EyeWideRight", "JawForward", "JawLeft", "JawRight", "JawOpen", "MouthClose", "MouthFunnel",
    "MouthPucker", "MouthLeft", "MouthRight", "MouthSmileLeft", "MouthSmileRight", "MouthFrownLeft",
    "MouthFrownRight", "MouthDimpleLeft", "MouthDimpleRight", "MouthStretchLeft", "MouthStretchRight",
    "MouthRollLower", "MouthRollUpper", "MouthShrugLower", "MouthShrugUpper", "MouthPressLeft", "MouthPressRight",
    "MouthLowerDownLeft", "MouthLowerDownRight", "MouthUpperUpLeft", "MouthUpperUpRight", "BrowDownLeft",
    "BrowDownRight", "BrowInnerUp", "BrowOuterUpLeft", "BrowOuterUpRight", "CheekPuff", "CheekSquintLeft",
    "CheekSquintRight", "NoseSneerLeft", "NoseSneerRight", "TongueOut",
)


@dataclass
class LiveLinkFrame:
    """A decoded packet: ``values`` (61,) float32 as the module docstring orders them."""

    device_id: str
    subject: str
    frame: int
    subframe: float
    fps_numerator: int
    fps_denominator: int
    values: np.ndarray


def value_names() -> list[str]:
    """The 61 value names of a packet, in packet order."""
    return list(PACKET_NAMES) + list(ROTATION_COLUMNS)


def packet_order(arkit_names) -> np.ndarray:
    """(52,) indices taking weights in ``arkit_names`` order (ARKit's lower-camel names, any order)
    to packet order."""
    position = {n[0].upper() + n[1:]: k for k, n in enumerate(arkit_names)}
    missing = [n for n in PACKET_NAMES if n not in position]
    if missing:
        raise InputError(f"the curves lack the Live Link blendshapes {', '.join(missing)}.")
    return np.array([position[n] for n in PACKET_NAMES])


def _string(text: str) -> bytes:
    raw = text.encode("utf-8")
    return struct.pack(">I", len(raw)) + raw


def encode(device_id: str, subject: str, frame: int, fps: int, arkit: np.ndarray, subframe: float = 0.0,
           rotations: np.ndarray | None = None) -> bytes:
    """One packet for ``arkit`` ((52,) weights in [0, 1] in packet order, :data:`PACKET_NAMES`)
    at ``frame`` of a ``fps`` frames/s stream; ``rotations`` (9,) radians, zeros when None."""
    values = np.zeros(VALUE_COUNT, ">f4")
    values[:52] = np.clip(np.asarray(arkit, np.float64), 0.0, 1.0)
    if rotations is not None:
        values[52:] = rotations
    return (struct.pack(">B", PACKET_VERSION) + _string(device_id) + _string(subject)
            + struct.pack(">ifii", int(frame), float(subframe), int(fps), 1) + struct.pack(">B", VALUE_COUNT)
            + values.tobytes())


def decode(packet: bytes) -> LiveLinkFrame:
    """Parse a packet (the layout of the module docstring); a malformed one raises InputError."""
    def fail(why: str):
        raise InputError(f"Live Link Face packet of {len(packet)} bytes: {why}.")

    def take(offset: int, n: int) -> bytes:
        if offset + n > len(packet):
            fail(f"it ends inside a field at byte {offset}")
        return packet[offset : offset + n]

    if take(0, 1)[0] != PACKET_VERSION:
        fail(f"packet version {packet[0]}, expected {PACKET_VERSION}")
    offset, strings = 1, []
    for _ in range(2):
        (n,) = struct.unpack(">I", take(offset, 4))
        strings.append(take(offset + 4, n).decode("utf-8", errors="replace"))
        offset += 4 + n
    frame, subframe, num, den = struct.unpack(">ifii", take(offset, 16))
    count = take(offset + 16, 1)[0]
    values = np.frombuffer(take(offset + 17, 4 * count), ">f4").astype(np.float32)
    if offset + 17 + 4 * count != len(packet):
        fail(f"{len(packet) - offset - 17 - 4 * count} bytes after the {count} values")
    return LiveLinkFrame(strings[0], strings[1], frame, subframe, num, den, values)


class LiveLinkSender:
    """Sends each frame (weights in ``arkit_names`` order) as a Live Link Face packet to
    ``host:port`` over UDP."""

    def __init__(self, host: str, port: int, subject: str, device_id: str, fps: float, arkit_names):
        if float(fps) != int(fps):
            raise InputError(f"Live Link frame rates are whole numbers; stream.fps is {fps}.")
        self.address = (host, int(port))
        self.subject, self.device_id, self.fps = subject, device_id, int(fps)
        self.order = packet_order(arkit_names)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)

    def send(self, frame_index: int, arkit: np.ndarray) -> None:
        weights = np.asarray(arkit, np.float64)[self.order]
        self.sock.sendto(encode(self.device_id, self.subject, frame_index, self.fps, weights), self.address)

    def close(self) -> None:
        self.sock.close()
