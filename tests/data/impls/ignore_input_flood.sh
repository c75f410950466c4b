#!/bin/sh
# Test impl: never reads its input and prints without end (yes).
exec yes 'not an answer'
