"""Prompts for a chat model driving the discovery tools."""

from __future__ import annotations

from lucifer.graphs.discovery.state import DiscoveryRequest, trace_text
from lucifer.kb import QueryOption

SYSTEM_PROMPT = """\
You advise a search-and-rescue robot which information-gathering query to run at its current \
location. You get the location signature (what is observed there), a short trace of the \
episode so far and the candidate query options with their descriptions.

Use the tools to look at telemetry memory before answering:
- signature_outcomes: what happened at exactly this signature before;
- similar_signatures: known signatures similar in meaning, with the options that worked there;
- option_fit: how well the signature fits each option's description (for unseen signatures);
- option_stats: how each option did overall.

Then answer with ONLY a JSON object, no other text:
{"recommendation": "<one candidate option>", "distribution": {"<option>": <probability>, ...}, \
"confidence": <probability that the recommendation is right, 0..1>}
The recommendation must be one of the candidate options, spelled exactly."""


def request_prompt(request: DiscoveryRequest, options: dict[str, QueryOption]) -> str:
    trace = "\n".join(f"- {trace_text(step)}" for step in request.trace) or "- (empty)"
    cands = "\n".join(f"- {name}: {options[name].description}" for name in request.options)
    return (
        f"Location signature: {request.signature}\n\n"
        f"Episode trace:\n{trace}\n\n"
        f"Candidate options:\n{cands}"
    )


def retry_prompt(reason: str, request: DiscoveryRequest) -> str:
    return (
        f"Your answer was rejected: {reason}. Answer again with only the JSON object; the "
        f"recommendation must be exactly one of: {', '.join(request.options)}."
    )
