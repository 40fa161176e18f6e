"""Head motion: its rotations, removing it from a capture (the rigid markers, paper Eq. 1-2)
and synthesizing it from pitch."""
