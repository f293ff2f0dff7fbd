"""Benchmarks and evaluations behind ``lucifer eval``."""
