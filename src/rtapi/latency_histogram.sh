#!/bin/sh
# latency-histogram: latency-test with a text histogram of each thread's wake-up jitter.
# Usage: latency-histogram [-t SECONDS] [--bin NS] [base_period [servo_period]]
bin=1000
n=$#
while [ "$n" -gt 0 ]; do
    # take the first argument off, keep it (at the end) unless it is --bin
    a=$1; shift; n=$((n - 1))
    case "$a" in
        --bin) [ "$n" -ge 1 ] || { echo "latency-histogram: --bin needs a value" >&2; exit 1; }
               bin=$1; shift; n=$((n - 1)) ;;
        --bin=*) bin=${a#--bin=} ;;
        --help|-h)
            echo "Usage: latency-histogram [-t SECONDS] [--bin NS] [base_period [servo_period]]"
            echo "Runs latency-test and prints a text histogram of each thread's wake-up jitter,"
            echo "in bins of NS nanoseconds (default 1000). Other options: see latency-test --help."
            exit 0 ;;
        *) set -- "$@" "$a" ;;
    esac
done
exec latency-test --histogram="$bin" "$@"
