#!/bin/bash
# The cluster test (label `cluster`, issue 23): a real Slurm on this machine.
# As root on Debian it installs what is missing (slurm-wlm, munge), starts
# munged, slurmctld and slurmd with a one-node configuration in a temporary
# folder, renders a small animation as 4 time windows with
# `hexant farm --submit`, kills one array task mid-run and requeues it
# (`scontrol requeue`), waits for the array and its join, and compares every
# frame, the contact sheet and the GIF byte for byte with one machine's
# render; then stops the daemons it started. Exit 77 (CTest: skipped) with
# the reason when not root or when Slurm cannot be installed or started.
#
#   bash tests/cluster/slurm_farm_test.sh build/hexant
set -u
hexant=$(readlink -f "${1:?usage: slurm_farm_test.sh HEXANT}")
skip() { echo "cluster test skipped: $*"; exit 77; }
fail() { echo "cluster test FAILED: $*"; exit 1; }

[ "$(id -u)" = 0 ] || skip "it needs root to install and start Slurm (run make test as root, as CI does)"
missing=""
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' $p 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  { apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing; } \
    > /dev/null 2>&1 || skip "apt-get could not install$missing"
fi

work=$(mktemp -d /tmp/hexant_cluster.XXXXXX)
conf=$work/slurm.conf
started_munge=0
cleanup() {
  export SLURM_CONF=$conf
  scancel --user=root > /dev/null 2>&1 || true
  for pid in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [ -s "$pid" ] && kill "$(cat "$pid")" 2> /dev/null
  done
  sleep 1
  pkill -9 -f "$conf" 2> /dev/null  # (whatever of them is left)
  [ $started_munge = 1 ] && pkill -x munged 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT

# One node, this machine; ports of its own so that no other Slurm is met.
host=$(hostname -s)
port=$((20000 + $$ % 20000))
mkdir -p "$work/state" "$work/spool"
cat > "$conf" <<CONF
ClusterName=hexanttest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=$port
SlurmdPort=$((port + 1))
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobRequeue=1
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=hexant Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf

# (A munged that answers is used as it is; pgrep would also see a zombie.)
if ! munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  mkdir -p /etc/munge /run/munge /var/log/munge /var/lib/munge
  [ -s /etc/munge/munge.key ] || dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2> /dev/null
  chown -R munge:munge /etc/munge /run/munge /var/log/munge /var/lib/munge 2> /dev/null
  chmod 400 /etc/munge/munge.key
  runuser -u munge -- /usr/sbin/munged > /dev/null 2>&1 || skip "munged does not start"
  started_munge=1
fi
# (Slurm's daemons need a credential at once: wait for munged to give one.)
for i in $(seq 1 50); do
  munge -n 2> /dev/null | unmunge > /dev/null 2>&1 && break
  sleep 0.2
done
munge -n 2> /dev/null | unmunge > /dev/null 2>&1 || skip "munge gives no credential"

slurmctld -f "$conf" > /dev/null 2>&1 || skip "slurmctld does not start ($(tail -2 "$work/slurmctld.log" 2> /dev/null))"
slurmd -f "$conf" > /dev/null 2>&1 || skip "slurmd does not start ($(tail -2 "$work/slurmd.log" 2> /dev/null))"
idle=0
deadline=$((SECONDS + 40))
while [ $SECONDS -lt $deadline ]; do
  timeout 5 sinfo -h -o %t 2> /dev/null | grep -q idle && { idle=1; break; }
  sleep 1
done
[ $idle = 1 ] || skip "the node did not come up ($(tail -2 "$work/slurmd.log" 2> /dev/null))"

# The animation: 16 frames, each window a few seconds' work.
cd "$work"
cat > scene.pov <<'POV'
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3 + 6 * clock, 5, -4>, rgb 1 area_light x, z, 3, 3 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
#declare I = 0;
#while (I < 8)
  sphere { <-2.8 + 0.8 * I, 0.4 + 0.3 * sin(2 * pi * (clock + I / 8)), 0>, 0.35
           pigment { rgb <0.9, 0.2 + 0.08 * I, 0.3> } translate z * clock }
  #declare I = I + 1;
#end
sphere { <0, 1, 2>, 0.8 pigment { rgb 0.2 } finish { reflection 0.5 } }
POV
flags=(scene.pov -W 96 -H 72 --frame-count 16 --spp 32 --threads 1)
"$hexant" render "${flags[@]}" -o one/f_####.png --contact-sheet one.png --animation one.gif > /dev/null 2>&1 \
  || fail "the one-machine render failed"

said=$("$hexant" farm "${flags[@]}" -o farm/f_####.png --windows 4 --contact-sheet farm.png \
         --animation farm.gif --farm-dir scripts --submit 2>&1) || fail "farm --submit: $said"
echo "$said"
array=$(echo "$said" | sed -n 's/^array job \([0-9]*\), join job.*/\1/p')
[ -n "$array" ] || fail "no job id in: $said"

# Kill one task mid-run and requeue it: its --resume finishes the window.
requeued=0
for i in $(seq 1 300); do
  state=$(squeue -h -j "${array}_1" -o %T 2> /dev/null)
  if [ "$state" = RUNNING ]; then
    sleep 1
    scontrol requeue "${array}_1" && requeued=1
    # (Slurm makes a requeued job wait about two minutes before it is
    # eligible again; this test need not.)
    sleep 1
    scontrol update JobId="${array}_1" StartTime=now > /dev/null 2>&1 || true
    break
  fi
  [ -z "$(squeue -h -j "${array}" 2> /dev/null)" ] && break
  sleep 0.2
done
[ $requeued = 1 ] || fail "task ${array}_1 was never seen running to requeue"
echo "requeued task ${array}_1 mid-run"

for i in $(seq 1 600); do
  [ -z "$(squeue -h 2> /dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h 2> /dev/null)" ] || fail "jobs still queued after 10 minutes: $(squeue)"

status=0
for f in one/f_*.png; do
  cmp -s "$f" "farm/$(basename "$f")" || { echo "differs: $(basename "$f")"; status=1; }
done
cmp -s one.png farm.png || { echo "the contact sheets differ"; status=1; }
cmp -s one.gif farm.gif || { echo "the animations differ"; status=1; }
[ -s scripts/stats.json ] || { echo "no merged statistics"; status=1; }
ls -a farm farm/.hexant | grep -q partial && { echo "a temporary was left"; status=1; }
# Every frame's record (app/frame_record.hpp), whole, the requeued task's too.
for f in farm/f_*.png; do
  [ -s "farm/.hexant/$(basename "$f").json" ] || { echo "no record for $f"; status=1; }
done
[ $status = 0 ] || { cat scripts/*.log; fail "the cluster's frames are not one machine's"; }
echo "16 frames, contact sheet and GIF from 4 Slurm array tasks (one requeued mid-run) identical to one machine's"
