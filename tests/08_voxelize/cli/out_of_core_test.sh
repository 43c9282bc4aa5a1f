#!/bin/bash
# ctest for `geolab voxelize --out-of-core` (lab 08's file-backed mode; the reference here, the student's code in
# the release):
#   out_of_core_test.sh GEOLAB DIR equal   the raw file written slab by slab is byte for byte the in-memory run's,
#                                          surface and solid, with slabs of 5 layers that cut the mesh (96³)
#   out_of_core_test.sh GEOLAB DIR peak N  bunny00's solid at N³ streamed to a file: prints the peak memory and
#                                          fails when it reaches 1 GiB (the file is removed after)
set -euo pipefail
geolab=$1
dir=$2
mkdir -p "$dir"
case $3 in
equal)
    for mode in "" --solid; do
        "$geolab" voxelize bunny00 --res 96 $mode --threads 2 --out "$dir/in-memory.raw" >/dev/null
        "$geolab" voxelize bunny00 --res 96 $mode --threads 2 --slab-layers 5 --out-of-core --out "$dir/out-of-core.raw"
        cmp "$dir/in-memory.raw" "$dir/out-of-core.raw"
        echo "bunny00 at 96³ ${mode:-(surface)}: the out-of-core file equals the in-memory one"
    done
    ;;
peak)
    trap 'rm -f "$dir/big.raw"' EXIT
    json=$("$geolab" voxelize bunny00 --res "$4" --solid --threads 2 --out-of-core --out "$dir/big.raw" --json)
    echo "$json"
    peak=$(echo "$json" | sed -n 's/.*"peak_rss_mib":\([0-9.eE+-]*\).*/\1/p')
    echo "peak memory at $4³: $peak MiB"
    awk -v p="$peak" 'BEGIN { exit !(p > 0 && p < 1024) }'
    echo "below 1 GiB"
    ;;
*)
    echo "usage: $0 GEOLAB DIR equal|peak N" >&2
    exit 2
    ;;
esac
