"""The domain layer: the methods of the papers and everything they need, on arrays and model
objects (one package a subject; docs/architecture.md shows which may import which)."""
