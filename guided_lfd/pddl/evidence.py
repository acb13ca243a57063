"""A learned action's evidence as the comment lines above it, and read back from them.

The writer puts, above each learned action, what its demonstrations showed
about each precondition (``(ontable ?y) 1/1``: held in 1 of 1), the
conditions they varied (not required), and the preconditions the teacher
confirmed (``confirmed``: a request to show the skill without it was
refused).  Reading a domain back reads them again, so a skill's evidence
travels with its PDDL file through ``merge``, ``excuse`` and ``teach``: the
skill excuses (:mod:`guided_lfd.excuse.skills`) relax only preconditions whose
evidence says they were never tested.  A comment that does not match the
action below it (a precondition edited away by hand) is ignored: a
precondition without evidence is never relaxed.
"""

from __future__ import annotations

import re
from dataclasses import replace

from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Evidence, Literal

__all__ = ["EVIDENCE_HEAD", "evidence_lines", "with_evidence_comments"]

#: The first words of an action's evidence comment.
EVIDENCE_HEAD = "evidence (held in / demonstrations):"

_ACTION = re.compile(r"^\s*\(\s*:action\s+([^\s()]+)", re.IGNORECASE)
_ITEM = re.compile(r"(\(\s*not\s*\([^()]*\)\s*\)|\([^()]*\))\s+(\d+)/(\d+)(\s+confirmed)?", re.IGNORECASE)


def evidence_lines(action: ActionSchema, width: int = 112) -> list[str]:
    """A learned action's evidence as comment lines: each precondition with the demonstrations it held in (of
    all), then the conditions some demonstration varied (not required); none for an action without it."""
    if not action.evidence:
        return []
    required, varied = action.learned_evidence()
    items = [f"{e}," for e in required] or ["no precondition"]
    items[-1] = items[-1].rstrip(",")
    if varied:
        items[-1] += ";"
        items += ["varied, so not required:", *(f"{e}," for e in varied)]
        items[-1] = items[-1].rstrip(",")
    lines = [EVIDENCE_HEAD]
    for item in items:  # an item is never split (a literal stays on one line)
        if len(lines[-1]) + 1 + len(item) > width:
            lines.append(" ")
        lines[-1] += f" {item}"
    return lines


def with_evidence_comments(domain: Domain, text: str) -> Domain:
    """``domain`` with each action's evidence read from the comments above it in its source ``text``."""
    if EVIDENCE_HEAD not in text:
        return domain
    found = _comment_evidence(text)
    if not found:
        return domain
    actions = [_attached(a, found.get(a.name, "")) for a in domain.actions]
    return replace(domain, actions=actions)


def _comment_evidence(text: str) -> dict[str, str]:
    """Each action's evidence comment, joined into one line of items (by the action's lower-case name)."""
    out: dict[str, str] = {}
    comments: list[str] = []
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith(";"):
            comments.append(stripped.lstrip(";").strip())
            continue
        match = _ACTION.match(line)
        if match:
            heads = [i for i, c in enumerate(comments) if c.startswith(EVIDENCE_HEAD)]
            if heads:
                out[match.group(1).lower()] = " ".join(comments[heads[-1]:])[len(EVIDENCE_HEAD):]
        comments = []
    return out


def _literal(text: str) -> Literal | None:
    """The literal an evidence item names (None: an empty one, ``()`` or ``(not ())``)."""
    words = text.lower().replace("(", " ").replace(")", " ").split()
    positive = not words or words[0] != "not"
    words = words if positive else words[1:]
    return Literal(Atom(words[0], tuple(words[1:])), positive) if words else None


def _attached(action: ActionSchema, items: str) -> ActionSchema:
    """``action`` with the evidence ``items`` that fit it: a precondition it has, or a condition shown varied."""
    if not items or action.evidence:
        return action
    pre = set(action.precondition)
    evidence = []
    for match in _ITEM.finditer(items):
        shown, demonstrations = int(match.group(2)), int(match.group(3))
        if not 0 <= shown <= demonstrations or demonstrations == 0:
            continue
        lit = _literal(match.group(1))
        if lit is None:
            continue
        required = shown == demonstrations
        if (lit in pre) == required:  # a required one must be a precondition; a varied one must not
            evidence.append(Evidence(lit, shown, demonstrations, bool(match.group(4)) and required))
    return replace(action, evidence=tuple(evidence)) if evidence else action
