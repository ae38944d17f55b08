#!/bin/bash
# display: prints to the (redirected) stdout
echo "display output"
