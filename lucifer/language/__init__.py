"""Offline language analysis for the builtin grounding backend (no LLM)."""
