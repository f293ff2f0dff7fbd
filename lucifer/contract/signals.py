"""The ``signals`` block of ``lucifer ground --json --signals CONTEXT.json``.

The grounding CLI calls :func:`signals_json` with the grounding result, the path given to
``--signals`` and the KB, and puts the returned dict under ``"signals"``. The context JSON
format is documented in :mod:`lucifer.contract.space`.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from lucifer.contract.space import ContextSpace, load_context_space
from lucifer.contract.transducer import build_contract
from lucifer.contract.types import ContractParams

if TYPE_CHECKING:
    from lucifer.kb.loader import KnowledgeBase


def signals_json(
    source: Any,
    space: ContextSpace | str | Path | Mapping[str, Any],
    kb: KnowledgeBase,
    params: ContractParams | None = None,
) -> dict[str, Any]:
    """The Signal Contract as plain JSON.

    ``source``: a GroundingResult, GroundedObjects, Beliefs or a BeliefSession. ``space``: a
    :class:`ContextSpace` or a context JSON (path, JSON text or dict); the JSON's ``params``
    apply unless ``params`` is given. Raises :class:`lucifer.errors.BadRequest` for a bad
    context JSON.
    """
    if not isinstance(space, ContextSpace):
        space, file_params = load_context_space(space, kb.rows, kb.cols)
        params = params or file_params
    return build_contract(source, space, kb, params).to_json_dict()
