#!/bin/bash
# --document writes a man page (section 9 for realtime comps) next to the input or to -o FILE.
set -e
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
here=$PWD
cp kinds.comp "$tmp/"
cd "$tmp"
halcompile --document kinds.comp
cat kinds.9
halcompile --document -o other/kinds.9 kinds.comp 2>&1 || echo "missing directory: exit $?"
mkdir other
halcompile -d -o other/kinds.9 kinds.comp
cmp kinds.9 other/kinds.9 && echo "same page with -o"
mkdir third
halcompile --document --keep-adoc=kept.txt -o third/kinds.9 kinds.comp
cmp kept.txt third/kinds.9 && echo "kept copy equals the page"
cp kinds.comp hc_doc_probe.comp
sed -i 's/^component kinds /component hc_doc_probe /' hc_doc_probe.comp
page=$EMC2_HOME/share/man/man9/hc_doc_probe.9
trap 'rm -rf "$tmp" "$page"' EXIT
halcompile --install-doc hc_doc_probe.comp
head -2 "$page" | tail -1
cp "$here/noapp.comp" .
halcompile --document noapp.comp
grep -A1 '^\.SH SYNOPSIS' noapp.9 | tail -1
