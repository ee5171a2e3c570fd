"""consistent-remesh over several processes: `mpirun -np N consistent-remesh
ARGS` shares the models out over the N ranks. Model i is read by rank
i mod N; rank 0 reads the base domain, or the rank that read
--base-domain-from's model builds it. Then each rank traces and
straightens the next model not yet taken whenever it has a free slot (a
counter all ranks share), reading it again if another rank read it. As
each model is straightened, its rank posts its figures to rank 0, which
reads its straightened surfaces back from the files written into the
output folder while the other models run. Once every model is done, rank 0
remeshes the collection and writes every collection file, the pictures and
the report, the same files as one process writes. Within a rank, its
models run in child processes as without MPI (a model that fails or
crashes fails alone, on any rank).

The ranks must see the same files (one machine, or a shared file system).
mpi4py (Debian's python3-mpi4py) carries the messages; it is imported only
when an MPI launcher started this process with more than one rank."""

import array
import atexit
import os
import time


# The variables by which Open MPI, MPICH (Hydra) and PMIx tell a process how
# many ranks its job has, and how many of them share its machine.
_SIZE_VARIABLES = ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE")
_LOCAL_SIZE_VARIABLES = ("OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "PMI_LOCAL_SIZE")


class SingleProcess:
    """The whole collection in this process."""

    rank = 0
    size = 1
    local_size = 1

    def owner(self, index):
        """The rank that reads model `index`."""
        return index % self.size

    def owns(self, index):
        """Whether model `index` is this rank's to read."""
        return self.owner(index) == self.rank

    def broadcast(self, value, root=0):
        """`value` of rank `root`, on every rank."""
        return value

    def gather(self, value):
        """On rank 0 the list of every rank's `value`, by rank; None on the
        others."""
        return [value]

    def all_gather(self, value):
        """On every rank the list of every rank's `value`, by rank."""
        return [value]

    def counter(self):
        """A counter shared by the ranks (collective): its claim() gives 0,
        1, 2, ... over all ranks together, each number to one rank only."""
        return _LocalCounter()

    def progress(self):
        """Lets MPI serve the other ranks' claims while this rank waits on
        its child processes."""

    def end(self, status):
        return status

    def use_every_core(self):
        pass


class _LocalCounter:
    def __init__(self):
        self.next = 0

    def claim(self):
        self.next += 1
        return self.next - 1

    def free(self):
        pass


class MPIRanks(SingleProcess):
    """The ranks of an MPI job (mpi4py's COMM_WORLD)."""

    def __init__(self, communicator):
        self.communicator = communicator
        self.rank = communicator.Get_rank()
        self.size = communicator.Get_size()
        self.local_size = _environment_count(_LOCAL_SIZE_VARIABLES) or 1
        self.posted = []  # the requests of the values posted

    def broadcast(self, value, root=0):
        return self.communicator.bcast(value, root=root)

    def gather(self, value):
        # Point to point, each rank waiting without spinning: a rank done
        # early leaves its core to the models still running.
        if self.rank != 0:
            for request in self.posted + [self.communicator.isend(value, dest=0, tag=_GATHER_TAG)]:
                _wait(request)
            self.posted = []
            return None
        values = [value] + [None] * (self.size - 1)
        for rank in range(1, self.size):
            values[rank] = _receive(self.communicator, rank, _GATHER_TAG)
        return values

    def post(self, value):
        """A rank other than 0: sends `value` to rank 0 without waiting for
        it to be received (rank 0's posts() has it; gather() waits until it
        has been)."""
        self.posted.append(self.communicator.isend(value, dest=0, tag=_POST_TAG))

    def posts(self, wait=False):
        """Rank 0: the values the other ranks have posted that arrived since
        the last call, in the order each rank posted them; with `wait`, at
        least one (waiting without spinning)."""
        values = []
        while True:
            for rank in range(1, self.size):
                while self.communicator.Iprobe(source=rank, tag=_POST_TAG):
                    values.append(self.communicator.recv(source=rank, tag=_POST_TAG))
            if values or not wait:
                return values
            time.sleep(_WAIT_SECONDS)

    def end(self, status):
        """Rank 0: sends the run's exit status to the other ranks. The
        others: waits for it (without spinning) and returns it."""
        if self.rank == 0:
            for rank in range(1, self.size):
                self.communicator.send(status, dest=rank, tag=_END_TAG)
            return status
        return _receive(self.communicator, 0, _END_TAG)

    def use_every_core(self):
        """Lets rank 0 use every core of its machine, now that the other
        ranks wait for it (sleeping, see end()): mpirun binds each rank to
        one core by default, and rank 0's remesh places models on several
        threads. Where the binding cannot be widened (a cpuset), it stays."""
        try:
            os.sched_setaffinity(0, range(os.cpu_count() or 1))
        except (AttributeError, OSError, ValueError):
            pass

    def all_gather(self, value):
        return self.communicator.allgather(value)

    def counter(self):
        return _SharedCounter(self.communicator)

    def progress(self):
        self.communicator.Iprobe()


class _SharedCounter:
    """One integer in rank 0's memory that every rank adds 1 to atomically
    (MPI one-sided fetch-and-op), so that the models go to whichever rank is
    free first."""

    def __init__(self, communicator):
        from mpi4py import MPI
        self.MPI = MPI
        size = MPI.LONG.Get_size()
        self.window = MPI.Win.Allocate(size if communicator.Get_rank() == 0 else 0, size, comm=communicator)
        if communicator.Get_rank() == 0:
            memory = self.window.tomemory()
            memory[:] = bytes(len(memory))
        communicator.Barrier()
        self.communicator = communicator

    def claim(self):
        one, previous = array.array("l", [1]), array.array("l", [0])
        self.window.Lock(0, self.MPI.LOCK_SHARED)
        self.window.Fetch_and_op(one, previous, 0, 0, self.MPI.SUM)
        self.window.Unlock(0)
        return previous[0]

    def free(self):
        """Collective: every rank has claimed its last number."""
        self.communicator.Barrier()
        self.window.Free()


_GATHER_TAG = 2801
_END_TAG = 2802
_POST_TAG = 2803
_WAIT_SECONDS = 0.02


def _wait(request):
    """Waits for an mpi4py send request, testing it every _WAIT_SECONDS: a
    blocking MPI call would keep a core busy while it waits."""
    while not request.test()[0]:
        time.sleep(_WAIT_SECONDS)


def _receive(communicator, source, tag):
    """The next object `source` sends with `tag`, received once it has
    arrived (probed every _WAIT_SECONDS). mpi4py's irecv() would receive
    into a buffer of fixed size, too small for a surface."""
    while not communicator.Iprobe(source=source, tag=tag):
        time.sleep(_WAIT_SECONDS)
    return communicator.recv(source=source, tag=tag)


def _environment_count(names):
    for name in names:
        try:
            return int(os.environ[name])
        except (KeyError, ValueError):
            continue
    return None


def this_job():
    """MPIRanks when an MPI launcher started this process as one of several
    ranks, else SingleProcess. The ranks fork their models' child processes
    (which never call MPI), so Open MPI's warning about fork is turned off.
    They send each other only a few small messages (the surfaces go through
    the output folder), so Open MPI carries them with its ob1 layer unless
    told otherwise: choosing UCX's transports took 0.2 s at every start."""
    if (_environment_count(_SIZE_VARIABLES) or 1) <= 1:
        return SingleProcess()
    os.environ.setdefault("OMPI_MCA_mpi_warn_on_fork", "0")
    os.environ.setdefault("OMPI_MCA_pml", "ob1")
    try:
        from mpi4py import MPI
    except ImportError as error:
        raise SystemExit("consistent-remesh: started by an MPI launcher with several ranks, but mpi4py cannot be "
                         "imported (%s): install python3-mpi4py, or run one process" % error)
    communicator = MPI.COMM_WORLD
    _serial_vtk_controller()
    return MPIRanks(communicator) if communicator.Get_size() > 1 else SingleProcess()


# The serial controller VTK gets instead of pvbatch's (kept alive here).
_SERIAL_CONTROLLER = []


def _serial_vtk_controller():
    """The ranks talk through mpi4py, and each filter runs on one rank's
    data (the collection's remesh, PCA and blends on rank 0 alone). Started
    as `pvbatch --symmetric`, VTK's global controller spans the ranks
    instead, and a filter's collective checks over it (the Semi-Regular
    Remesher's) wait forever for ranks that never call them: VTK gets a
    serial controller."""
    try:
        from vtkmodules.vtkParallelCore import vtkDummyController, vtkMultiProcessController
    except ImportError:
        return
    controller = vtkMultiProcessController.GetGlobalController()
    if controller is None or controller.GetNumberOfProcesses() <= 1:
        return
    serial = vtkDummyController()
    _SERIAL_CONTROLLER.extend([serial, controller])
    vtkMultiProcessController.SetGlobalController(serial)
    # The script ends in sys.exit, which leaves pvbatch before it finalizes
    # MPI through its controller: this process does it then.
    def finalize():
        vtkMultiProcessController.SetGlobalController(controller)
        controller.Finalize()
    atexit.register(finalize)


def default_jobs(ranks):
    """How many models a rank runs at once by default: the cores this
    process may use, shared among the ranks on its machine."""
    try:
        cores = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        cores = os.cpu_count() or 1
    return max(1, cores // max(1, ranks.local_size))
