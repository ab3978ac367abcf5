#!/bin/bash
# run.sh READER FILE [MAX] [REPEAT] [VMEM_KB]: one run under ulimit -v (default 4000000 KB) and timeout 120 s
R=$1; F=$2; MAX=${3:-1000}; REP=${4:-1}; VM=${5:-4000000}
out=$( (ulimit -v $VM; ulimit -s 8192; timeout 120 /usr/bin/time -f "__TIME %e s wall, peak RSS %M KB, exit %x" ./target/release/reader-crates $R inputs/$F $MAX $REP) 2>&1 )
rc=$?
echo "[$R $F max=$MAX] rc=$rc"
echo "$out" | sed 's/^/   /' | cut -c1-400
