#!/usr/bin/env python3
# Test impl, right under a convention: a polygonizer that fills by the
# even-odd rule, so it returns only the faces inside an odd number of
# boundaries (`dcel diff --answer even-odd` agrees; without it, a note names
# the kind).
import json
import _correct
import _reference


def answer(text):
    return json.dumps(_reference.answer(text, "even-odd"))


_correct.serve(answer)
