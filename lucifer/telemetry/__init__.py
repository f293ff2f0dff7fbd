"""Telemetry: cross-episode memory of query outcomes and the scenarios that generate them."""

from lucifer.telemetry.memory import OptionStat, TelemetryMemory, TelemetryRecord, signature_key
from lucifer.telemetry.scenarios import (
    OPTIONS,
    QUERY_INFO_TYPE,
    sample_candidates,
    sample_signature,
)

__all__ = [
    "OPTIONS",
    "QUERY_INFO_TYPE",
    "OptionStat",
    "TelemetryMemory",
    "TelemetryRecord",
    "sample_candidates",
    "sample_signature",
    "signature_key",
]
