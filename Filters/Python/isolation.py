"""Each model's stages in a child process of their own, so that nothing one
model does can take the others down: a crash inside a third-party library
(a segfault or an abort in VTK's readers on a hostile file, an uncaught
std::bad_alloc) ends the child only, and the model fails with a message
saying how the child died.

The child is forked from this process, so it starts with everything this
process has (the models read so far, the base domain, the filters) and
costs no start-up; it sends back its result pickled through a pipe, with
surfaces as VTK XML text. VTK runs its Sequential SMP backend here and the
core starts no threads, so a fork copies no thread that holds a lock.

A child that has not finished after the timeout (consistent-remesh
--model-timeout) is killed, and the stage fails with "timed out after N s".

For the tests, CMP_TEST_CRASH=STAGE:NAME:SIGNAL[,...] makes the child of
model NAME's stage STAGE (read or process) kill itself with SIGNAL (for
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


def _crash_for_the_test(stage, name):
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
        _crash_for_the_test(stage, name)
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


def _read_until(read_end, deadline):
    """Everything the child writes into `read_end` until it closes it, or
    None if `deadline` (time.monotonic(); None: no deadline) passes first."""
    chunks = []
    with os.fdopen(read_end, "rb", buffering=0) as pipe:
        while True:
            if deadline is not None:
                left = deadline - time.monotonic()
                if left <= 0 or not select.select([pipe], [], [], left)[0]:
                    return None
            chunk = pipe.read(1 << 20)
            if not chunk:
                return b"".join(chunks)
            chunks.append(chunk)


def run_in_child(stage, name, function, doing, timeout=0):
    """Runs `function()` in a forked child and returns its result, which
    must pickle. A StageError in the child is raised here with its message
    (and its `extra`, see `with_extra`); any other exception becomes a
    StageError naming it; a child that dies raises a StageError "crashed
    while DOING: ..." saying how, and one still running after `timeout`
    seconds (0: no limit) is killed and raises "timed out after N s while
    DOING". `stage` and `name` are for CMP_TEST_CRASH."""
    sys.stdout.flush()
    sys.stderr.flush()
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(read_end)
        _child(write_end, stage, name, function)
    os.close(write_end)
    data = _read_until(read_end, time.monotonic() + timeout if timeout > 0 else None)
    if data is None:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        raise StageError("timed out after %g s while %s: the process doing it was killed (--model-timeout)"
                         % (timeout, doing))
    _, status = os.waitpid(pid, 0)
    if data:
        try:
            outcome = pickle.loads(data)
        except Exception:
            outcome = None
        if outcome and outcome[0] == "ok":
            return outcome[1]
        if outcome and outcome[0] == "stage error":
            raise with_extra(StageError(outcome[1]), outcome[2])
        if outcome:
            raise StageError("unexpected error in consistent-remesh: %s" % outcome[1])
    if os.WIFSIGNALED(status):
        how = "was killed by %s" % _signal_description(os.WTERMSIG(status))
    elif os.WIFEXITED(status):
        how = "exited with status %d" % os.WEXITSTATUS(status)
    else:
        how = "ended with wait status %d" % status
    raise StageError("crashed while %s: the process doing it %s" % (doing, how))


# What a model's stage does, for the message of a crash.
MODEL_STAGES = {"read": "reading and checking its files", "process": "tracing and straightening its net"}


def run_model_stage(model, stage, function, surfaces, timeout=0):
    """`function()`, one stage of `model` (a stages.Model), in a child
    process: afterwards model.report and the Model attributes named in
    `surfaces` ("surface", "parameterized", "curves") are what the child
    left them. `stage` is a key of MODEL_STAGES; `timeout` as for
    run_in_child. Raises StageError if the stage failed, the child crashed
    or timed out; model.report then keeps the figures the child had written
    before a StageError."""
    def child():
        try:
            function()
        except StageError as error:
            raise with_extra(error, model.report)
        return model.report, [polydata_to_text(getattr(model, attribute)) for attribute in surfaces]

    try:
        report, texts = run_in_child(stage, model.name, child, MODEL_STAGES[stage], timeout)
    except StageError as error:
        if getattr(error, "extra", None) is not None:
            model.report = error.extra
        raise
    model.report = report
    for attribute, text in zip(surfaces, texts):
        setattr(model, attribute, polydata_from_text(text))


def with_extra(error, extra):
    """`error` carrying `extra` (what the child had done before it failed,
    picklable) back to the parent."""
    error.extra = extra
    return error
