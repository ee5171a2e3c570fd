"""Each model's stages in a child process of their own, so that nothing one
model does can take the others down: a crash inside a third-party library
(a segfault or an abort in VTK's readers on a hostile file, an uncaught
std::bad_alloc) ends the child only, and the model fails with a message
saying how the child died.

The child is forked from this process, so it starts with everything this
process has (the models read so far, the base domain, the filters) and
costs no start-up; it sends back its result pickled through a pipe, with
surfaces as VTK XML text. VTK runs its Sequential SMP backend here and the
core's only threads (the remesh's) have ended when it returns, so a fork
copies no thread that holds a lock. Several children may run at once
(run_children's `jobs`).

A child that has not finished after the timeout (consistent-remesh
--model-timeout) is killed, and the stage fails with "timed out after N s".

For the tests, CMP_TEST_CRASH=STAGE:NAME:SIGNAL[,...] makes the child of
model NAME's stage STAGE (read or process; for the collection's stages
NAME is "collection", see collection_stages) kill itself with SIGNAL (for
example SIGSEGV or SIGABRT; SIGSEGV for a name the signal module does not
know) before it starts: a crash that no input file is needed for. SIGNAL
HANG makes it sleep for a day instead: a hang."""

import os
import pickle
import select
import signal
import sys
import time
import traceback

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from .vtkio import StageError


def polydata_to_text(polydata):
    """`polydata` as the text of an uncompressed binary .vtp (None stays
    None): every array, field data included, comes back as it was."""
    if polydata is None:
        return None
    writer = vtkXMLPolyDataWriter()
    writer.WriteToOutputStringOn()
    writer.SetDataModeToBinary()
    writer.SetCompressorTypeToNone()
    writer.SetInputData(polydata)
    if not writer.Write() or writer.GetErrorCode():
        raise StageError("cannot pass a surface back from the child process")
    return writer.GetOutputString()


def polydata_from_text(text):
    """The surface `polydata_to_text` wrote (None stays None)."""
    if text is None:
        return None
    reader = vtkXMLPolyDataReader()
    reader.ReadFromInputStringOn()
    reader.SetInputString(text)
    reader.Update()
    return reader.GetOutput()


def _signal_description(number):
    try:
        name = signal.Signals(number).name
    except ValueError:
        return "signal %d" % number
    description = signal.strsignal(number)
    return "%s, %s" % (name, description) if description else name


def crash_for_the_test(stage, name):
    """The CMP_TEST_CRASH hook (see the module's description)."""
    for entry in os.environ.get("CMP_TEST_CRASH", "").split(","):
        parts = entry.strip().split(":")
        if len(parts) == 3 and parts[0] == stage and parts[1] == name:
            if parts[2] == "HANG":
                time.sleep(86400)
            os.kill(os.getpid(), getattr(signal, parts[2], signal.SIGSEGV))


def _child(write_end, stage, name, function):
    """In the child: runs `function`, pickles ("ok", result), ("stage
    error", message, extra) or ("error", message) into `write_end` and ends
    the process without running this interpreter's exit handlers."""
    code = 0
    try:
        crash_for_the_test(stage, name)
        try:
            outcome = ("ok", function())
        except StageError as error:
            outcome = ("stage error", str(error), getattr(error, "extra", None))
        except Exception as error:  # a bug in this package, told as such
            outcome = ("error", "%s: %s (at %s)" % (type(error).__name__, error,
                                                   traceback.extract_tb(error.__traceback__)[-1].name))
        with os.fdopen(write_end, "wb") as pipe:
            pickle.dump(outcome, pipe, protocol=pickle.HIGHEST_PROTOCOL)
    except BaseException:
        code = 1
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        finally:
            os._exit(code)


# The outcome of a task that another process ran (run_children's claim).
NOT_RUN = object()


class _Child:
    """One forked child running `function` (see run_children), and what it
    has written into its pipe so far."""

    def __init__(self, stage, name, function, doing, timeout):
        self.doing = doing
        self.timeout = timeout
        self.chunks = []
        sys.stdout.flush()
        sys.stderr.flush()
        read_end, write_end = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(read_end)
            _child(write_end, stage, name, function)
        os.close(write_end)
        self.pid = pid
        self.pipe = os.fdopen(read_end, "rb", buffering=0)
        self.deadline = time.monotonic() + timeout if timeout > 0 else None

    def fileno(self):
        return self.pipe.fileno()

    def read_some(self):
        """Reads what the child has written; True once it has closed its
        end (finished or died)."""
        chunk = self.pipe.read(1 << 20)
        if chunk:
            self.chunks.append(chunk)
            return False
        return True

    def kill(self):
        """The outcome of a child still running at its deadline: it is
        killed."""
        os.kill(self.pid, signal.SIGKILL)
        os.waitpid(self.pid, 0)
        self.pipe.close()
        return StageError("timed out after %g s while %s: the process doing it was killed (--model-timeout)"
                          % (self.timeout, self.doing))

    def outcome(self):
        """The result of a child that has closed its pipe, or the StageError
        saying why there is none (see run_in_child)."""
        self.pipe.close()
        _, status = os.waitpid(self.pid, 0)
        data = b"".join(self.chunks)
        if data:
            try:
                outcome = pickle.loads(data)
            except Exception:
                outcome = None
            if outcome and outcome[0] == "ok":
                return outcome[1]
            if outcome and outcome[0] == "stage error":
                return with_extra(StageError(outcome[1]), outcome[2])
            if outcome:
                return StageError("unexpected error in consistent-remesh: %s" % outcome[1])
        if os.WIFSIGNALED(status):
            how = "was killed by %s" % _signal_description(os.WTERMSIG(status))
        elif os.WIFEXITED(status):
            how = "exited with status %d" % os.WEXITSTATUS(status)
        else:
            how = "ended with wait status %d" % status
        return StageError("crashed while %s: the process doing it %s" % (self.doing, how))


# How often a process that shares its tasks with other MPI ranks lets MPI
# serve their claims while its children run (seconds).
POLL_SECONDS = 0.05


def run_children(tasks, jobs=1, claim=None, poll=None, done=None):
    """Runs each task (stage, name, function, doing, timeout) as
    run_in_child does, up to `jobs` children at once, and returns one
    outcome per task, in the tasks' order: the function's result, or the
    StageError that run_in_child would raise (an exception object, not
    raised). Each task's function runs in a child forked when the task
    starts, so it sees what the parent had then; the outcomes do not depend
    on `jobs`. `done(index, outcome)`, if given, is called as soon as a
    task's outcome is known, while the other children run on.

    With `claim`, the tasks are shared with other processes: claim() gives
    the index of the next task to run here (an index past the last: none
    left), and the outcomes of the tasks run elsewhere are NOT_RUN.
    `poll()`, if given, is called every POLL_SECONDS while children run."""
    outcomes = [NOT_RUN] * len(tasks)
    order = iter(range(len(tasks)))
    running = {}  # _Child -> task index
    left = True
    while True:
        while left and len(running) < max(1, jobs):
            index = next(order, None) if claim is None else claim()
            if index is None or index >= len(tasks):
                left = False
                break
            running[_Child(*tasks[index])] = index
        if not running:
            return outcomes
        deadlines = [child.deadline for child in running if child.deadline is not None]
        wait = max(0.0, min(deadlines) - time.monotonic()) if deadlines else None
        if poll is not None:
            wait = POLL_SECONDS if wait is None else min(wait, POLL_SECONDS)
        ready, _, _ = select.select(list(running), [], [], wait)
        ended = [(running.pop(child), child.outcome) for child in ready if child.read_some()]
        now = time.monotonic()
        ended += [(running.pop(child), child.kill) for child in list(running)
                  if child.deadline is not None and child.deadline <= now]
        for index, outcome in ended:
            outcomes[index] = outcome()
            if done is not None:
                done(index, outcomes[index])
        if poll is not None:
            poll()


def run_in_child(stage, name, function, doing, timeout=0):
    """Runs `function()` in a forked child and returns its result, which
    must pickle. A StageError in the child is raised here with its message
    (and its `extra`, see `with_extra`); any other exception becomes a
    StageError naming it; a child that dies raises a StageError "crashed
    while DOING: ..." saying how, and one still running after `timeout`
    seconds (0: no limit) is killed and raises "timed out after N s while
    DOING". `stage` and `name` are for CMP_TEST_CRASH."""
    outcome = run_children([(stage, name, function, doing, timeout)])[0]
    if isinstance(outcome, StageError):
        raise outcome
    return outcome


# What a model's stage does, for the message of a crash.
MODEL_STAGES = {"read": "reading and checking its files", "process": "tracing and straightening its net"}


def run_model_stages(stages, jobs=1, timeout=0, claim=None, poll=None, finished=None):
    """Runs one stage of each of several models, each in a child process,
    up to `jobs` at once: `stages` holds (model, stage, function, surfaces),
    with `model` a stages.Model, `stage` a key of MODEL_STAGES, `function()`
    the stage's work and `surfaces` the Model attributes it sets
    ("surface", "parameterized", "curves"); `timeout` as for run_in_child,
    `claim` and `poll` as for run_children. As soon as a model's child
    ends, its report and those attributes are what the child left them,
    and `finished(index in stages, error)` is called, if given. Returns
    {index in `stages`: None, or the StageError (not raised) if the stage
    failed, its child crashed or timed out} for the stages run here; the
    model's report then keeps the figures the child had written before a
    StageError."""
    def task(model, stage, function, surfaces):
        def child():
            try:
                function()
            except StageError as error:
                raise with_extra(error, model.report)
            return model.report, [polydata_to_text(getattr(model, attribute)) for attribute in surfaces]
        return (stage, model.name, child, MODEL_STAGES[stage], timeout)

    errors = {}

    def take(index, outcome):
        model, _, _, surfaces = stages[index]
        if isinstance(outcome, StageError):
            if getattr(outcome, "extra", None) is not None:
                model.report = outcome.extra
            errors[index] = outcome
        else:
            model.report, texts = outcome
            for attribute, text in zip(surfaces, texts):
                setattr(model, attribute, polydata_from_text(text))
            errors[index] = None
        if finished is not None:
            finished(index, errors[index])

    run_children([task(*entry) for entry in stages], jobs, claim, poll, take)
    return errors


def with_extra(error, extra):
    """`error` carrying `extra` (what the child had done before it failed,
    picklable) back to the parent."""
    error.extra = extra
    return error
