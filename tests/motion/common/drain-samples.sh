#!/bin/bash
# Print every sample buffered in sampler.0 (threads already stopped) and return when drained.
timeout "${1:-1}" halsampler
exit 0
