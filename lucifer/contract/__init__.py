"""The Signal Contract: priors, potentials and admissible options from grounded beliefs.

Build one from a grounding result (or a :class:`BeliefSession`) and a client's
:class:`ContextSpace`::

    from lucifer.contract import GridContextSpace, build_contract
    contract = build_contract(result, GridContextSpace(kb.rows, kb.cols), kb)
    contract.admissible["2,3"], contract.priors["2,3"]["N"], contract.potentials["2,3"]

See :mod:`lucifer.contract.transducer` for the equations and
:mod:`lucifer.contract.space` for the context JSON of ``lucifer ground --signals``.
"""

from lucifer.contract.beliefs import (
    BeliefChange,
    BeliefParams,
    BeliefSession,
    IngestOutcome,
    confirm,
)
from lucifer.contract.signals import signals_json
from lucifer.contract.space import (
    MOVE_DELTAS,
    ContextSpace,
    ExplicitContextSpace,
    GridContextSpace,
    SpaceTable,
    load_context_space,
)
from lucifer.contract.transducer import (
    ContractTables,
    as_beliefs,
    beliefs_from_objects,
    build_contract,
    build_tables,
    shaping,
)
from lucifer.contract.types import (
    STATUS_ORDER,
    Belief,
    BeliefState,
    ContextStatus,
    ContractParams,
    EquationCase,
    Provenance,
    SignalContract,
)

__all__ = [
    "MOVE_DELTAS",
    "STATUS_ORDER",
    "Belief",
    "BeliefChange",
    "BeliefParams",
    "BeliefSession",
    "BeliefState",
    "ContextSpace",
    "ContextStatus",
    "ContractParams",
    "ContractTables",
    "EquationCase",
    "ExplicitContextSpace",
    "GridContextSpace",
    "IngestOutcome",
    "Provenance",
    "SignalContract",
    "SpaceTable",
    "as_beliefs",
    "beliefs_from_objects",
    "build_contract",
    "build_tables",
    "confirm",
    "load_context_space",
    "shaping",
    "signals_json",
]
