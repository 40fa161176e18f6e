"""Speech: the utterance (phones, times, emotions), forced alignment and phone recognition in
every language, pitch and loudness."""
