"""Handlers of ``lucifer ground``, ``lucifer kb ...`` and ``lucifer trace ...``."""

from __future__ import annotations

import argparse
import asyncio
import json
import sys
from typing import Any

from lucifer.errors import BadReport


def read_report(arg: str | None) -> str:
    """The report from the argument, or from stdin for ``-``/no argument (must be UTF-8)."""
    if arg is not None and arg != "-":
        return arg
    if sys.stdin is None or sys.stdin.isatty():
        raise BadReport("no report given: pass TEXT or pipe it on stdin")
    data = sys.stdin.buffer.read()
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise BadReport(f"stdin is not valid UTF-8: byte 0x{data[exc.start]:02x} at offset {exc.start} "
                        f"({exc.reason}); nothing was grounded") from exc


def _grounder(args: argparse.Namespace) -> Any:
    from lucifer.grounding import Grounder

    return Grounder(args.kb, getattr(args, "model", None), chroma_url=getattr(args, "chroma_url", None),
                    base_url=getattr(args, "base_url", None), retries=getattr(args, "retries", None),
                    timeout_s=getattr(args, "timeout", None))


def cmd_ground(args: argparse.Namespace) -> int:
    text = read_report(args.text)

    async def run() -> Any:
        g = _grounder(args)
        try:
            return g, await g.ground(text)
        finally:
            await g.aclose()

    g, result = asyncio.run(run())
    payload = result.spec_dict()
    if result.denied:
        payload["denied"] = [o.spec_dict() for o in result.denied]
    if result.errors:
        payload["errors"] = result.errors
    if args.signals:
        from lucifer.contract.signals import signals_json

        payload["signals"] = signals_json(result, args.signals, g.kb)
    if args.json:
        print(json.dumps(payload, ensure_ascii=False))
        return 0
    print(f"report: {result.report}")
    if not result.objects:
        print("objects: (none: nothing groundable was claimed)")
    for o in result.objects:
        via = f"  via {o.via}" if o.via else ""
        print(f"  {o.location:<18} {o.category:<12} cells={o.cells}  ({o.entity!r}){via}")
    for o in result.denied:
        print(f"  denied: {o.location}/{o.category} ({o.cue!r})")
    if result.status.value != "ok":
        print(f"status: {result.status.value}: {'; '.join(result.errors)}")
    if args.signals:
        print(json.dumps(payload["signals"], indent=1)[:4000])
    print(f"trace: {result.trace_id}   (lucifer trace show {result.trace_id})")
    return 0


def cmd_kb_validate(args: argparse.Namespace) -> int:
    from lucifer.kb import KBError, load_kb, resolve_kb_dir

    try:
        kb = load_kb(args.kb)
    except KBError as exc:
        print(f"{resolve_kb_dir(args.kb)}: INVALID ({len(exc.problems)} problem(s))")
        for p in exc.problems:
            print(f"  - {p}")
        return 1
    print(f"{kb.root}: OK — {len(kb.categories)} categories, {len(kb.landmarks)} landmarks on a "
          f"{kb.rows}x{kb.cols} grid, {len(kb.relations)} relations, {len(kb.glossary)} glossary terms, "
          f"{len(kb.query_options)} query options")
    return 0


def cmd_kb_show(args: argparse.Namespace) -> int:
    from lucifer.kb import load_kb

    kb = load_kb(args.kb)
    if args.json:
        print(json.dumps({
            "categories": [c.model_dump(mode="json") for c in kb.categories],
            "grid": {"rows": kb.rows, "cols": kb.cols},
            "landmarks": [lm.model_dump(mode="json") for lm in kb.landmarks],
            "relations": [r.model_dump() for r in kb.relations],
            "glossary": [t.model_dump() for t in kb.glossary],
            "query_options": [o.model_dump() for o in kb.query_options],
        }, indent=1))
        return 0
    print(f"knowledge base {kb.root}")
    print("\nInformation Space:")
    for c in kb.categories:
        print(f"  {c.name:<14} {c.role.value:<12} {c.description}")
    width = max(len(lm.name) for lm in kb.landmarks)
    width = min(width, 14)
    print(f"\nmap ({kb.rows}x{kb.cols}, row 0 = north):")
    for r in range(kb.rows):
        print("  " + " | ".join(f"{kb.cell_owner.get((r, c), '.')[:width]:<{width}}" for c in range(kb.cols)))
    print("\nlandmarks:")
    for lm in kb.landmarks:
        print(f"  {lm.name:<18} cells={[list(c) for c in lm.cells]}  aliases: {', '.join(lm.aliases) or '-'}")
    print("\nrelations:")
    for rel in kb.relations:
        print(f"  {rel.subject} {rel.relation} {rel.object}")
    print("\nglossary:")
    for t in kb.glossary:
        print(f"  {t.term:<22} -> {t.category}")
    if kb.query_options:
        print("\nquery options:")
        for o in kb.query_options:
            print(f"  {o.name:<22} {o.description}")
    return 0


def cmd_kb_index(args: argparse.Namespace) -> int:
    from lucifer.embeddings import get_embedder
    from lucifer.kb import load_kb
    from lucifer.retrieval import make_client, open_collection, sync_index

    kb = load_kb(args.kb)
    emb = get_embedder()
    col = open_collection(make_client(kb.root, args.chroma_url), kb.root, emb)
    print(sync_index(kb, col, emb, force=True).summary())
    return 0


def cmd_trace_list(args: argparse.Namespace) -> int:
    import datetime as dt

    from lucifer.traces import list_runs

    runs = list_runs(args.limit)
    if not runs:
        print("no traces yet: run `lucifer ground TEXT` first")
        return 0
    for r in runs:
        when = dt.datetime.fromtimestamp(r["created"]).strftime("%Y-%m-%d %H:%M:%S")
        report = r["report"].replace("\n", " ")
        report = report if len(report) <= 60 else report[:57] + "..."
        print(f"{r['trace_id']}  {when}  {r['backend']:<10} {r['status']:<14} {r['n_objects']:>2} obj  {report}")
    return 0


def cmd_trace_prune(args: argparse.Namespace) -> int:
    from lucifer.traces import prune_runs

    if args.keep is None and args.older_than is None:
        print("lucifer trace prune: say what to delete: --keep N and/or --older-than DAYS", file=sys.stderr)
        return 2
    for flag, value in (("--keep", args.keep), ("--older-than", args.older_than)):
        if value is not None and value < 0:
            print(f"lucifer trace prune: {flag} must not be negative, got {value}", file=sys.stderr)
            return 2
    r = prune_runs(args.keep, args.older_than, vacuum=not args.no_vacuum)
    mb = 1024 * 1024
    print(f"removed {r['removed']} runs, kept {r['kept']}; {r['path']}: "
          f"{r['bytes_before'] / mb:.1f} MB -> {r['bytes_after'] / mb:.1f} MB")
    return 0


def cmd_trace_show(args: argparse.Namespace) -> int:
    from lucifer.traces import format_run, load_run

    run = asyncio.run(load_run(args.trace_id))
    if args.json:
        print(json.dumps(run, ensure_ascii=False, default=str, indent=1))
    else:
        print(format_run(run))
    return 0
