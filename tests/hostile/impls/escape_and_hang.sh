#!/bin/sh
# A command that starts a grandchild in a session of its own (setsid puts
# it out of reach of a kill of the command's process group), then never
# answers: dcel diff times out and must take the grandchild down too.
# DCEL_HOSTILE_MARK (a number of seconds, unique per test) names the
# grandchild for ps.
setsid sleep "$DCEL_HOSTILE_MARK" &
cat >/dev/null
exec sleep "$DCEL_HOSTILE_MARK"
