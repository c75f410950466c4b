#!/usr/bin/env python3
# Test impl, right under a convention: a polygonizer in the GEOS/Turf
# tradition that never attaches holes, so every ring is a polygon of its own:
# each bounded face's outer boundary, filled in (`dcel diff --holes-unattached`
# agrees; without it, a note names the option).
import json
import _correct
import _reference


def answer(text):
    rings = _reference.answer(text, "rings")["rings"]
    return json.dumps({"polygons": [[ring] for ring in rings]})


_correct.serve(answer)
