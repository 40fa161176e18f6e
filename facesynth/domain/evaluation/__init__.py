"""Scoring synthesized motion: against held-out takes and their ground truth, the fair baselines
beside it, and bootstrap intervals."""
