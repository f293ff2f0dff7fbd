"""LangGraph graphs: grounding (language -> contract objects) and discovery (telemetry -> query)."""
