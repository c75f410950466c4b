#!/usr/bin/env python3
# Test impl: correct, except that it reverses one cycle: the first whose
# reverse is a different cycle (a tree's cycle reads the same both ways).
import json
import _correct


def rotations(c):
    return {tuple(c[i:] + c[:i]) for i in range(len(c))}


def answer(text):
    faces = json.loads(_correct.correct(text))["faces"]
    for i, c in enumerate(faces):
        if tuple(c[::-1]) not in rotations(c):
            faces[i] = c[::-1]
            break
    return json.dumps({"faces": faces})


_correct.serve(answer)
