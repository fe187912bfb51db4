"""A misspelled keyword named with a did-you-mean, instead of pybind11's dump of C++ signatures.

pybind11 answers a call it cannot match with "incompatible function arguments" and every
overload's signature. Where a keyword the call gave is in none of them, that is almost always
the mistake: `with_keyword_hints` turns the error into "add_joint(): no keyword 'q00'; did you
mean 'q0'? It takes name, type, parent, child, axis, …"."""

import difflib
import functools
import re

# "(self: X, name: str, *, parent: str, axis: object = None) -> Y": the parameter names.
_PARAMETER = re.compile(r"[(,]\s*(\w+)\s*:")


def _parameters(message):
    names = []
    for line in message.splitlines():
        if re.match(r"\s*\d+\. \(", line):
            for name in _PARAMETER.findall(line.split(") ->")[0]):
                if name != "self" and name not in names:
                    names.append(name)
    return names


def with_keyword_hints(function, name=None):
    """`function` (a pybind11 function or method), its unknown keywords named with a hint."""
    label = name or function.__name__

    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            message = str(error)
            if "incompatible function arguments" not in message or not kwargs:
                raise
            known = _parameters(message)
            unknown = [key for key in kwargs if key not in known]
            if not known or not unknown:
                raise
            key = unknown[0]
            close = difflib.get_close_matches(key, known, n=1, cutoff=0.6)
            hint = f"; did you mean '{close[0]}'?" if close else ""
            raise TypeError(f"{label}(): no keyword '{key}'{hint} It takes "
                            f"{', '.join(known)}") from None

    return call
