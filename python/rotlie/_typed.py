"""A call defined in C++ with ``**keywords`` given the signature ``help()`` and ``inspect`` show: its
keywords' names, annotations and defaults come from the C++ table that defines them (the binary
scene's request, runs/binary_fields.hpp), so nothing here spells them again."""
from __future__ import annotations

import ast
import functools
import inspect


def typed(function, keywords, returns: str):
    """``function`` (keywords only) with the signature of ``keywords``: (name, annotation, default, help),
    the default as Python writes it or "" when required; the registered force terms are ``**terms``."""
    parameters = [
        inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, annotation=annotation,
                          default=inspect.Parameter.empty if default == "" else ast.literal_eval(default))
        for name, annotation, default, _ in keywords]
    parameters.append(inspect.Parameter("terms", inspect.Parameter.VAR_KEYWORD, annotation="Sequence[float] | str"))

    @functools.wraps(function)
    def call(**keywords):
        return function(**keywords)

    call.__signature__ = inspect.Signature(parameters, return_annotation=returns)
    call.__wrapped__ = None
    del call.__wrapped__
    call.__module__ = "rotlie"
    return call
