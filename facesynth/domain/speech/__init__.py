"""The voice: forced alignment and phone recognition of speech, its pitch and its loudness."""
