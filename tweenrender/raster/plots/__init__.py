"""Diagrams, one module each: the correspondence picture, the Q-curve plot, the storyboard sheet."""
