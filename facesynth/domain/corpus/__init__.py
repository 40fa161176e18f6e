"""The built-in sample corpus: a virtual actress reading a phoneme-balanced corpus in four emotions."""
