"""Procedural sample levels with known ground truth (see ``levels``)."""
