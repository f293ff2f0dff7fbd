"""Telemetry: cross-episode memory of query outcomes and the scenarios that generate them."""
