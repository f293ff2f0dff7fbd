"""The grounding graph: retrieve -> extract -> classify -> ground -> validate (-> retry | fallback)."""

from __future__ import annotations

from typing import Any

from langgraph.graph import END, START, StateGraph

from lucifer.graphs.grounding.context import GroundingContext
from lucifer.graphs.grounding.nodes import (
    classify_claims,
    extract_places,
    fallback_builtin,
    ground_cells,
    retrieve_context,
    route_after_extract,
    route_after_validate,
    validate_objects,
)
from lucifer.graphs.grounding.state import GroundingInput, GroundingOutput, GroundingState


def build_graph() -> StateGraph:
    builder = StateGraph(GroundingState, context_schema=GroundingContext,
                         input_schema=GroundingInput, output_schema=GroundingOutput)
    builder.add_node(retrieve_context)
    builder.add_node(extract_places)
    builder.add_node(classify_claims)
    builder.add_node(ground_cells)
    builder.add_node(validate_objects)
    builder.add_node(fallback_builtin)

    builder.add_edge(START, "retrieve_context")
    builder.add_edge("retrieve_context", "extract_places")
    builder.add_conditional_edges("extract_places", route_after_extract, ["classify_claims", "fallback_builtin"])
    builder.add_edge("classify_claims", "ground_cells")
    builder.add_edge("ground_cells", "validate_objects")
    builder.add_conditional_edges("validate_objects", route_after_validate,
                                  ["extract_places", "fallback_builtin", END])
    builder.add_edge("fallback_builtin", END)
    return builder


def compile_graph(checkpointer: Any = None) -> Any:
    graph = build_graph().compile(checkpointer=checkpointer)
    graph.name = "grounding"
    return graph
