#!/bin/sh
echo child ran "$@"
