#!/bin/sh
# with_few_fds.sh FREE COMMAND [ARG...]: runs COMMAND with exactly FREE file
# descriptor numbers free below its limit (RLIMIT_NOFILE), whatever this
# shell inherited: a fixed `ulimit -n` depends on what the caller left open,
# and a CI runner may pass several descriptors down.
free=$1; shift
limit=0
while [ "$free" -gt 0 ]; do
    [ -e "/proc/$$/fd/$limit" ] || free=$((free - 1))
    limit=$((limit + 1))
done
ulimit -n "$limit"
exec "$@"
