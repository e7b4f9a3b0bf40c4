#!/usr/bin/env bash
# Builds the firmware for thumbv7em-none-eabihf, runs its checks on QEMU's mps2-an386 (a
# Cortex-M4F) with semihosting, runs the control build that must fail, and prints the flash
# cost (.text and .rodata) of the size probes. Needs qemu-system-arm; .ci/run installs it.
set -euo pipefail
cd "$(dirname "$0")"
rustup target list --installed | grep -q '^thumbv7em-none-eabihf$' \
  || rustup target add thumbv7em-none-eabihf

cargo build --release --bins
out=$(timeout 600 cargo run --release --bin check) || { echo "$out"; echo "firmware check failed"; exit 1; }
echo "$out"
grep -q '^ALL PASS$' <<<"$out"

# The control: one wrong golden value must fail the run, through QEMU's exit status.
if timeout 600 cargo run --release --features broken --bin check --target-dir target/broken; then
  echo "the firmware passed with a wrong golden value"; exit 1
fi

printf '\nflash cost (bytes; release, opt-level s, LTO):\n%-12s %8s %8s\n' probe .text .rodata
for b in size_none size_warp size_direct size_all check; do
  size -A "target/thumbv7em-none-eabihf/release/$b" \
    | awk -v b="$b" '/^\.text/{t=$2} /^\.rodata/{r=$2} END{printf "%-12s %8d %8d\n", b, t, r}'
done
