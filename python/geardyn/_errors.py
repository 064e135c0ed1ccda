"""Argument errors in Python terms for the compiled classes and functions.

pybind11 reports a call it cannot match as "incompatible constructor arguments" with every
overload's signature. geardyn's wrappers read those signatures and say what is wrong: a required
keyword argument that is missing ("Gear(): face_width is required"), an unknown one with the
closest known name ("modul: did you mean 'module'?"), or a wrong type.
"""

import difflib
import functools
import re

_SIGNATURE = re.compile(r"^\s*(?:\d+\.\s*)?[\w.]+\((.*)\)(?:\s*->.*)?$")


def _parameters(doc):
    """[(names, required)] per overload, from a pybind11 docstring."""
    overloads = []
    for line in (doc or "").splitlines():
        match = _SIGNATURE.match(line)
        if not match:
            continue
        names, required = [], set()
        depth, current, parts = 0, "", []
        for ch in match.group(1):  # split on top-level commas only
            if ch in "([{<":
                depth += 1
            elif ch in ")]}>":
                depth -= 1
            if ch == "," and depth == 0:
                parts.append(current)
                current = ""
            else:
                current += ch
        parts.append(current)
        for part in parts:
            part = part.strip()
            if not part or part in ("*", "/") or part.startswith("self"):
                continue
            name = part.split(":")[0].split("=")[0].strip()
            names.append(name)
            if "=" not in part:
                required.add(name)
        overloads.append((names, required))
    return overloads


def explain(qualname, doc, args, kwargs):
    """The message for a call of ``qualname`` that pybind11 could not match, or None."""
    overloads = _parameters(doc)
    if not overloads:
        return None
    # The overload that accepts most of the given keywords.
    names, required = max(overloads, key=lambda o: sum(k in o[0] for k in kwargs))
    problems = []
    for key in kwargs:
        if key not in names:
            close = difflib.get_close_matches(key, names, n=1, cutoff=0.6)
            problems.append(f"unknown argument {key!r}" + (f" (did you mean {close[0]!r}?)"
                                                           if close else
                                                           f"; it takes {', '.join(names)}"))
    given = set(kwargs) | set(names[:len(args)])
    missing = [n for n in names if n in required and n not in given]
    problems += [f"{n} is required" for n in missing]
    if not problems:
        return None
    return f"{qualname}(): " + "; ".join(problems)


def checked_function(function, qualname):
    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            if "incompatible function arguments" not in str(error):
                raise
            message = explain(qualname, function.__doc__, args, kwargs)
            if message is None:
                raise
            raise TypeError(message) from None
    return call


def check_class(cls):
    """Makes the constructor of compiled class ``cls`` explain bad arguments (in place, so
    that objects the library returns are instances of the same class)."""
    original = cls.__init__
    init_doc = original.__doc__

    def __init__(self, *args, **kwargs):
        try:
            original(self, *args, **kwargs)
        except TypeError as error:
            if "incompatible constructor arguments" not in str(error):
                raise
            message = explain(cls.__name__, init_doc, args, kwargs)
            if message is None:
                raise
            raise TypeError(message) from None

    __init__.__doc__ = init_doc
    cls.__init__ = __init__
    return cls
