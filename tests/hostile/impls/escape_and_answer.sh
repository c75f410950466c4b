#!/bin/sh
# A command that answers correctly (the Python example) but first leaves a
# daemon behind: a double fork into a new session, whose parent exits at
# once, so the daemon is orphaned while the command still runs. In a
# session of its own, that daemon starts one more process in yet another
# session, so that taking it down hands dcel a new orphan.
# Usage: escape_and_answer.sh PYTHON EXAMPLE [--stream]
( setsid sh -c 'setsid sleep "$DCEL_HOSTILE_MARK" & exec sleep "$DCEL_HOSTILE_MARK"' & )
python=$1 example=$2
shift 2
exec "$python" "$example" "$@"
