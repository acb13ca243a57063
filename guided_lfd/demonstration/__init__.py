"""Demonstrations: VR hand traces, their segmentation, and the skills learned from them."""
