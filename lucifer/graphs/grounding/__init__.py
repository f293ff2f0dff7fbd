"""Grounding graph: report text -> validated contract objects."""

from lucifer.graphs.grounding.context import GroundingContext
from lucifer.graphs.grounding.graph import build_graph, compile_graph
from lucifer.graphs.grounding.state import GroundingInput, GroundingOutput, GroundingState

__all__ = ["GroundingContext", "GroundingInput", "GroundingOutput", "GroundingState", "build_graph", "compile_graph"]
