"""Parameter coercion without pydantic for the values that need no conversion.

Typer (0.2x) coerces every parameter value through a pydantic ``TypeAdapter``,
built on first use; importing pydantic and building the adapters is about
0.1 s, a third of ``guided-lfd excuse``'s start-up on a small task, although
most values need nothing done to them: an option left at its default (None, a
default string, an Enum member) or a string argument.

:class:`QuickCoercionMixin` gives each parameter of a command a :class:`QuickCoercion`
that returns such values itself, with exactly the result typer's adapter
would give, and hands every other value (numbers, paths, anything unusual,
every value it cannot vouch for, and every error) to typer's own coercion, so
messages and results stay typer's.  On a typer without this mechanism (no
``get_runtime_param``), it changes nothing.
"""

from __future__ import annotations

from enum import Enum
from typing import Any, get_args, get_origin

try:  # typer's own choice matching, the one its choice adapter calls
    from typer._param_types import coerce_cli_choice
except ImportError:  # another typer: choices go the full way
    coerce_cli_choice = None


class QuickCoercion:
    """A parameter's runtime coercion: trivial values here, the rest through typer's."""

    def __init__(self, param: Any) -> None:
        self._param = param
        self._typer: Any = None  # typer's RuntimeParam, built only when a value needs it
        desc = param.type_descriptor
        info = desc.parameter_info
        self._plain = info.parser is None and desc.file_annotation is None
        annotation = desc.annotation
        self._item = get_args(annotation)[0] if get_origin(annotation) is list else None
        self._annotation = annotation
        self._case_sensitive = info.case_sensitive

    def _full(self) -> Any:
        if self._typer is None:
            from typer._coercion import build_runtime_param

            self._typer = build_runtime_param(self._param.type_descriptor)
        return self._typer

    def coerce(self, value: Any, param: Any, ctx: Any) -> Any:
        """The coerced value: as typer's ``RuntimeParam.coerce`` returns it."""
        multi = param.multiple or param.nargs == -1
        if value is None:  # typer's RuntimeParam.coerce answers this before any adapter
            return () if multi else None
        if self._plain:
            annotation = self._annotation
            if annotation is str and type(value) is str:
                return value  # typer's str adapter: str(value), unchanged
            if (multi and self._item is str and isinstance(value, (list, tuple))
                    and all(type(v) is str for v in value)):
                return list(value)  # its list adapter validates each item as above, into a list
            if isinstance(annotation, type) and issubclass(annotation, Enum):
                if isinstance(value, annotation):
                    return value  # a default member: typer's choice matching returns it as is
                if coerce_cli_choice is not None and type(value) is str:
                    try:
                        return coerce_cli_choice(value, choices=list(annotation),
                                                 case_sensitive=self._case_sensitive, ctx=ctx)
                    except Exception:  # no match: typer's adapter words the error
                        pass
        return self._full().coerce(value, param=param, ctx=ctx)


def quicken(param: Any) -> None:
    """Give one typer parameter a :class:`QuickCoercion` (unless it has a coercion already)."""
    if (hasattr(param, "get_runtime_param") and hasattr(param, "type_descriptor")
            and getattr(param, "_runtime_param", False) is None):
        param._runtime_param = QuickCoercion(param)


class QuickCoercionMixin:
    """For a typer command or group class: its parameters, ``--help`` included, coerce quickly."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        for param in self.params:  # type: ignore[attr-defined]
            quicken(param)

    def get_help_option(self, ctx: Any) -> Any:
        """The ``--help`` option, made on first use like every other parameter's coercion."""
        option = super().get_help_option(ctx)  # type: ignore[misc]
        if option is not None:
            quicken(option)
        return option
