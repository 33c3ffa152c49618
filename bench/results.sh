#!/bin/sh
# Regenerates every figure of the documentation: doc/results/*.md and the
# README's generated blocks (bench/first_run.sh, bench/suite.sh,
# bench/denoise.sh, bench/bounces.sh, bench/error_split.sh,
# bench/instancing.sh).
# usage: bench/results.sh
set -eu
cd "$(dirname "$0")/.."
bench/first_run.sh
bench/suite.sh
bench/denoise.sh
bench/bounces.sh
bench/error_split.sh
bench/instancing.sh
