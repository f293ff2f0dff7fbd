"""User-facing errors: the CLI prints their message and exits with ``exit_code``."""

from __future__ import annotations


class LuciferError(Exception):
    exit_code = 2


class BadReport(LuciferError):
    """The report text cannot be grounded (empty, too long, not UTF-8)."""


class BadRequest(LuciferError):
    """A JSON request or a data file is malformed."""


class BackendError(LuciferError):
    """A backend name or model string is unusable."""
