"""A one-node Slurm cluster in a temporary folder, for tests: munged, slurmctld and slurmd from
Debian's packages, each with its configuration, sockets, state and logs in that folder, on free
ports, started in the foreground as our own children and stopped by their process ids.

    with SlurmCluster(folder) as cluster:     # raises ClusterError saying why it could not start
        subprocess.run(["sbatch", ...], env=cluster.env)
"""

import os
import shutil
import socket
import subprocess
import time


class ClusterError(Exception):
    pass


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def log_tail(path, lines=15):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError:
        return "(no log at %s)" % path


class SlurmCluster:
    PROGRAMS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "scancel", "sinfo")

    def __init__(self, folder, cpus=None):
        self.folder = os.path.abspath(folder)
        self.cpus = cpus or os.cpu_count() or 1
        self.node = socket.gethostname().split(".")[0]
        self.daemons = []  # (name, Popen, log path)
        self.env = dict(os.environ, SLURM_CONF=os.path.join(self.folder, "slurm.conf"))

    @classmethod
    def missing_programs(cls):
        return [p for p in cls.PROGRAMS if not shutil.which(p) and not os.path.exists("/usr/sbin/" + p)]

    def path(self, name):
        return os.path.join(self.folder, name)

    def __enter__(self):
        try:
            self.start()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc):
        self.stop()

    def start(self):
        os.makedirs(self.folder, exist_ok=True)
        for sub in ("ctld", "spool", "munge"):
            os.makedirs(self.path(sub), mode=0o700, exist_ok=True)
        os.chmod(self.path("munge"), 0o700)
        with open(self.path("munge/munge.key"), "wb") as key:
            key.write(os.urandom(1024))
        os.chmod(self.path("munge/munge.key"), 0o400)
        self.write_config()
        munge_socket = self.path("munge/munge.socket")
        self.launch("munged", ["munged", "--foreground", "--force", "--socket=" + munge_socket,
                               "--key-file=" + self.path("munge/munge.key"),
                               "--pid-file=" + self.path("munge/munged.pid"),
                               "--seed-file=" + self.path("munge/munged.seed"),
                               "--log-file=" + self.path("munged.log")], self.path("munged.log"))
        self.wait_for(lambda: os.path.exists(munge_socket), "munged", self.path("munged.log"), 10)
        self.launch("slurmctld", ["slurmctld", "-D", "-i", "-f", self.path("slurm.conf")], self.path("slurmctld.log"))
        self.wait_for(lambda: self.quiet(["scontrol", "ping"]) and "UP" in self.output(["scontrol", "ping"]),
                      "slurmctld", self.path("slurmctld.log"), 30)
        self.launch("slurmd", ["slurmd", "-D", "-N", self.node, "-f", self.path("slurm.conf")], self.path("slurmd.log"))
        self.wait_for(lambda: self.output(["sinfo", "-h", "-N", "-o", "%T"]).strip() in ("idle", "mixed"),
                      "slurmd", self.path("slurmd.log"), 60)

    def write_config(self):
        ports = free_port(), free_port()
        config = """\
# A one-node test cluster; every path is inside this folder.
ClusterName=pfxtest
SlurmctldHost={node}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={d_port}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={folder}/munge/munge.socket
StateSaveLocation={folder}/ctld
SlurmdSpoolDir={folder}/spool
SlurmctldPidFile={folder}/slurmctld.pid
SlurmdPidFile={folder}/slurmd.pid
SlurmctldLogFile={folder}/slurmctld.log
SlurmdLogFile={folder}/slurmd.log
# No cgroups in a container: track processes by their parents, bind nothing.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=3600
KillWait=5
NodeName={node} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN
PartitionName=test Nodes={node} Default=YES MaxTime=INFINITE State=UP
""".format(node=self.node, folder=self.folder, ctld_port=ports[0], d_port=ports[1], cpus=self.cpus)
        with open(self.path("slurm.conf"), "w") as f:
            f.write(config)

    def launch(self, name, command, log):
        out = open(self.path(name + ".stdout"), "w")
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, env=self.env)
        self.daemons.append((name, process, log))

    def wait_for(self, ready, name, log, seconds):
        deadline = time.time() + seconds
        process = self.daemons[-1][1]
        while time.time() < deadline:
            if process.poll() is not None:
                raise ClusterError("%s exited with code %d at start; its log:\n%s%s" % (
                    name, process.returncode, log_tail(log), log_tail(self.path(name + ".stdout"))))
            if ready():
                return
            time.sleep(0.2)
        raise ClusterError("%s did not come up within %d s; its log:\n%s%s" % (
            name, seconds, log_tail(log), log_tail(self.path(name + ".stdout"))))

    def output(self, command):
        result = subprocess.run(command, capture_output=True, text=True, env=self.env)
        return result.stdout if result.returncode == 0 else ""

    def quiet(self, command):
        return subprocess.run(command, capture_output=True, env=self.env).returncode == 0

    def stop(self):
        # slurmd first (it ends its job steps), then the controller, then munged; each by its id.
        for name, process, _ in reversed(self.daemons):
            if process.poll() is None:
                process.terminate()
                try:
                    process.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()
        self.daemons = []
