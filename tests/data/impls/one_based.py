#!/usr/bin/env python3
# Test impl: answers for the wrong number of vertices: vertex ids counted from 1.
import json
import _correct


def answer(text):
    faces = json.loads(_correct.correct(text))["faces"]
    return json.dumps({"faces": [[v + 1 for v in cycle] for cycle in faces]})


_correct.serve(answer)
