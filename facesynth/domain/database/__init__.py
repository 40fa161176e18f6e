"""The motion-node database as data to inspect and clean: contamination (paper V) and the
phoneme-Isomaps (paper IV)."""
