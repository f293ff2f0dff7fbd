"""The ``lucifer`` command line.

Heavy modules are imported inside the handlers so ``lucifer --help`` and a cold
``lucifer ground`` stay fast. Each command's arguments are declared in its own ``_add_*``
function below; the handler lives next to the feature it drives.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Sequence

Handler = Callable[[argparse.Namespace], int]


def _kb_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--kb", default=None, help="knowledge base directory (default: $LUCIFER_KB, else knowledge_base/)")


def _backend_args(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--model",
        default=None,
        help="grounding backend: builtin (default), rule, ner, or a chat model as provider:model "
        "(ollama:qwen3:8b, openai:MODEL, llamacpp:/path/model.gguf, llamacpp:gemma3-270m); "
        "default $LUCIFER_MODEL, else builtin",
    )
    p.add_argument("--chroma-url", default=None, help="talk to a Chroma server (default $LUCIFER_CHROMA_URL, else a local persistent store)")
    p.add_argument("--base-url", default=None, help="base URL for openai:/ollama: chat models")
    p.add_argument("--retries", type=int, default=None, help="validation retries before the fallback (default 2)")
    p.add_argument("--timeout", type=float, default=None, help="seconds before a chat model call is abandoned (default 60)")


def _lazy(module: str, func: str) -> Handler:
    def run(args: argparse.Namespace) -> int:
        import importlib

        return int(getattr(importlib.import_module(module), func)(args) or 0)

    return run


def _add_ground(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("ground", help="ground one report into contract objects (SPEC §2)")
    _kb_arg(p)
    _backend_args(p)
    p.add_argument("--json", action="store_true", help="print one JSON object (SPEC §2)")
    p.add_argument("--signals", metavar="CONTEXT.json", default=None,
                   help="also print Signal Contract signals for the client context space in this file")
    p.add_argument("text", nargs="?", default=None, help="the report; '-' or omitted reads stdin")
    p.set_defaults(func=_lazy("lucifer.commands", "cmd_ground"))


def _add_kb(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("kb", help="validate or show a knowledge base")
    kb_sub = p.add_subparsers(dest="kb_cmd", required=True)
    v = kb_sub.add_parser("validate", help="check every rule of SPEC §1; exit 1 listing each problem")
    _kb_arg(v)
    v.set_defaults(func=_lazy("lucifer.commands", "cmd_kb_validate"))
    s = kb_sub.add_parser("show", help="print the knowledge base as a map and tables")
    _kb_arg(s)
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_lazy("lucifer.commands", "cmd_kb_show"))
    x = kb_sub.add_parser("index", help="sync the vector index with the KB now (it also syncs by itself)")
    _kb_arg(x)
    x.add_argument("--chroma-url", default=None)
    x.set_defaults(func=_lazy("lucifer.commands", "cmd_kb_index"))


def _add_trace(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("trace", help="inspect checkpointed grounding runs")
    t_sub = p.add_subparsers(dest="trace_cmd", required=True)
    ls = t_sub.add_parser("list", help="recent runs, newest first")
    ls.add_argument("--limit", type=int, default=20)
    ls.set_defaults(func=_lazy("lucifer.commands", "cmd_trace_list"))
    sh = t_sub.add_parser("show", help="every node's input and output, in order")
    sh.add_argument("trace_id")
    sh.add_argument("--json", action="store_true")
    sh.set_defaults(func=_lazy("lucifer.commands", "cmd_trace_show"))
    pr = t_sub.add_parser("prune", help="delete old traces and give the space back "
                                        "(the store also keeps only the newest $LUCIFER_TRACE_KEEP runs, default 20000)")
    pr.add_argument("--keep", type=int, default=None, help="keep the newest N runs")
    pr.add_argument("--older-than", type=float, default=None, metavar="DAYS", help="delete runs older than DAYS")
    pr.add_argument("--no-vacuum", action="store_true", help="skip compacting the file (faster, frees no disk)")
    pr.set_defaults(func=_lazy("lucifer.commands", "cmd_trace_prune"))


def _add_eval(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("eval", help="benchmarks: grounding, discovery, ablation, backends")
    e_sub = p.add_subparsers(dest="eval_cmd", required=True)

    g = e_sub.add_parser("grounding", help="async batch evaluation of a grounding dataset (SPEC §3)")
    _kb_arg(g)
    _backend_args(g)
    g.add_argument("--dataset", required=True, action="append", help="JSONL dataset (repeatable)")
    g.add_argument("--predictions", default=None, help="write one JSON line per report here")
    g.add_argument("--concurrency", type=int, default=8)
    g.add_argument("--json", dest="json_out", default=None, metavar="OUT", help="write the JSON summary here")
    g.add_argument("--errors", action="store_true", help="list every miss with expected, predicted and trace id")
    g.add_argument("--no-progress", action="store_true", help="hide the progress bar")
    g.add_argument("--limit", type=int, default=None, help="only the first N reports")
    g.set_defaults(func=_lazy("lucifer.evals.grounding", "cmd_eval_grounding"))

    b = e_sub.add_parser("backends", help="regenerate the README backends table and chart")
    _kb_arg(b)
    b.add_argument("--out", default="benchmarks/results", help="directory for the JSON, markdown and PNG")
    b.add_argument("--backends", default=None, help="comma-separated subset")
    b.add_argument("--llm-limit", type=int, default=30, help="reports per regime for the slow LLM backends")
    b.set_defaults(func=_lazy("lucifer.evals.backends", "cmd_eval_backends"))

    d = e_sub.add_parser("discovery", help="replay the discovery benchmark (SPEC §4)")
    _kb_arg(d)
    d.add_argument("--model", default=None, help="discovery backend: builtin (default) or provider:model")
    d.add_argument("--json", dest="json_out", default=None, metavar="OUT")
    d.add_argument("--dataset", default=None, help="benchmark JSONL (default: the shipped one)")
    d.set_defaults(func=_lazy("lucifer.evals.discovery", "cmd_eval_discovery"))

    a = e_sub.add_parser("ablation", help="baseline / +G / +D / +D+G for one client (SPEC §5)")
    _kb_arg(a)
    a.add_argument("--client", required=True, help="rl, planner, minigrid")
    a.add_argument("--runs", type=int, default=40)
    a.add_argument("--episodes", type=int, default=1000)
    a.add_argument("--seed", type=int, default=0)
    a.add_argument("--json", dest="json_out", default=None, metavar="OUT")
    a.add_argument("--charts", default=None, metavar="DIR", help="also write PNG charts here")
    a.set_defaults(func=_lazy("lucifer.evals.ablation", "cmd_eval_ablation"))


def _add_discover(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("discover", help="one discovery request, JSON in and out (SPEC §4)")
    _kb_arg(p)
    p.add_argument("--model", default=None)
    p.add_argument("--memory", default=None, help="telemetry memory SQLite file")
    p.add_argument("request", nargs="?", default=None, help="request JSON, a file path, or '-' for stdin")
    p.set_defaults(func=_lazy("lucifer.graphs.discovery.cli", "cmd_discover"))


def _add_demo(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("demo", help="a short mission: reports stream in, the contract updates, the client finishes")
    _kb_arg(p)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--out", default="out/demo", help="where to write the PNG")
    p.set_defaults(func=_lazy("lucifer.demo", "cmd_demo"))


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="lucifer", description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--version", action="version", version="lucifer 0.1.0")
    sub = parser.add_subparsers(dest="command", required=True)
    for add in (_add_ground, _add_kb, _add_trace, _add_eval, _add_discover, _add_demo):
        add(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    from lucifer.errors import LuciferError

    try:
        return int(args.func(args) or 0)
    except LuciferError as exc:
        print(f"lucifer: error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
