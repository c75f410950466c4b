#!/usr/bin/env python3
# Test impl: right, but it reads the graph with its own number pattern, which
# knows 3, -0.5 and 1e-300 but not an exponent with a '+' sign (1e+16, 3E+00):
# those documents come out garbled and the program fails.
import re
import _correct

NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:[eE]-?\d+)?")


def answer(text):
    # Every number must match the pattern in full; anything else is an error.
    for token in re.findall(r"-?[0-9][0-9.eE+\-]*", text):
        if not NUMBER.fullmatch(token):
            raise ValueError("cannot read the number " + token)
    return _correct.correct(text)


_correct.serve(answer)
