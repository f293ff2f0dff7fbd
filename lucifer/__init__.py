"""LUCIFER: a Signal Contract for online language grounding and discovery in decision-making."""

__version__ = "0.1.0"
