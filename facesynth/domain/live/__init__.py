"""Live synthesis (``facesynth stream``): audio arriving in chunks, frames of rig curves out with a
fixed latency and no frame revised after it is sent.

- :mod:`.synthesizer`: the transport-free core, :class:`~.synthesizer.LiveSynthesizer` (phones in, frames out),
  with the fixed-lag DP or the greedy search over a sliding window.
- :mod:`.voice_frames`: frames from the voice's articulation model as audio arrives.
- :mod:`.phones`: phones as they become known: pocketsphinx's live phone-loop decoding, or the
  timings a TTS engine gives.
- :mod:`.livelink`: the Live Link Face UDP packet (encoder and decoder).
- :mod:`.server`: the transports: standard input to JSON lines, and a WebSocket server.

See docs/live.md.
"""
