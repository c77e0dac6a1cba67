#!/usr/bin/env python3
"""`modsynth serve` from the outside: its JSON API and every limit it
promises (README.md, "serve"). Each check starts its own server on a free
loopback port and stops it; every wait is bounded, so a hung server fails
the test instead of hanging it.

usage: serve_test.py MODSYNTH_BINARY SOURCE_DIR
"""
import http.client
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time

BIN, ROOT = sys.argv[1], sys.argv[2]
ROSE = os.path.join(ROOT, "tasks", "rose.json")
OUT_OF_REACH = os.path.join(ROOT, "tasks", "infeasible", "out-of-reach.task.json")
DISCONNECTED = os.path.join(ROOT, "tests", "fixtures", "invalid", "disconnected.json")
SPATIAL = os.path.join(ROOT, "tests", "fixtures", "spatial", "s3-0001.task.json")
SPATIAL_OUT_OF_REACH = os.path.join(ROOT, "tests", "fixtures", "spatial", "sir-0001.task.json")
# Runs to its time limit: for checks that act on a solve still running.
SLOW = os.path.join(ROOT, "tests", "fixtures", "serve", "slow.task.json")
JSON_TYPE = {"Content-Type": "application/json"}

failures = []
checks = 0


def check(cond, what):
    global checks
    checks += 1
    if not cond:
        failures.append(what)
        print("FAIL:", what, flush=True)


def read(path):
    with open(path, "rb") as f:
        return f.read()


class Server:
    """One `modsynth serve --port 0` process; the port comes from its first line."""

    def __init__(self, *options):
        self.proc = subprocess.Popen([BIN, "serve", "--port", "0", *options],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not m:
            self.proc.kill()
            raise RuntimeError("serve printed no URL: %r %s" % (line, self.proc.stderr.read()))
        self.port = int(m.group(1))

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
                failures.append("serve did not stop on SIGTERM")
        return self.proc.returncode

    def request(self, method, path, body=None, headers=None, timeout=30):
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)
        try:
            conn.request(method, path, body=body, headers=headers or {})
            res = conn.getresponse()
            data = res.read()
            return res.status, dict(res.getheaders()), data
        finally:
            conn.close()

    def raw(self, data, timeout=5):
        """Sends bytes as they are, then reads the reply to its end: (status, body)."""
        with socket.create_connection(("127.0.0.1", self.port), timeout=timeout) as sock:
            sock.sendall(data)
            sock.shutdown(socket.SHUT_WR)
            reply = b""
            while True:
                chunk = sock.recv(65536)
                if not chunk:
                    break
                reply += chunk
        m = re.match(rb"HTTP/1\.1 (\d{3}) ", reply)
        return (int(m.group(1)) if m else None), reply.partition(b"\r\n\r\n")[2]

    def json(self, method, path, body=None, headers=None):
        status, headers, data = self.request(method, path, body, headers)
        try:
            return status, headers, json.loads(data)
        except ValueError:
            return status, headers, {"unparsed": data[:200]}

    def solve(self, task_path, query=""):
        return self.json("POST", "/api/solve" + query, read(task_path), JSON_TYPE)

    def job(self, job_id):
        return self.json("GET", "/api/jobs/" + job_id)[2]

    def wait(self, job_id, cond, seconds, poll=0.1):
        """Polls the job (which also keeps it alive) until cond(job) holds."""
        deadline = time.monotonic() + seconds
        job = self.job(job_id)
        while not cond(job) and time.monotonic() < deadline:
            time.sleep(poll)
            job = self.job(job_id)
        return job

    def alive(self):
        try:
            return self.request("GET", "/api/info", timeout=5)[0] == 200 and self.proc.poll() is None
        except OSError:
            return False

    @staticmethod
    def execed_solve(pid):
        """Whether the child has exec'd the solve (before that it runs the server's image)."""
        try:
            with open("/proc/%d/cmdline" % pid, "rb") as f:
                return b"\0solve\0" in f.read()
        except OSError:
            return False

    def children(self):
        """Process ids whose parent is the server (its running solves)."""
        kids = []
        for pid in os.listdir("/proc"):
            if not pid.isdigit():
                continue
            try:
                with open("/proc/%s/stat" % pid) as f:
                    fields = f.read().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == self.proc.pid and fields[0] != "Z":
                kids.append(int(pid))
        return kids


def done(job):
    return job.get("done") is True


def running_with_progress(job):
    return done(job) or len(job.get("log", [])) > 0


# ------------------------------------------------------------------ checks

def test_page_and_info():
    with Server() as s:
        status, headers, body = s.request("GET", "/")
        check(status == 200 and b"<svg id=\"canvas\"" in body, "GET / serves the editor page")
        check(headers.get("Content-Type", "").startswith("text/html"), "page is text/html")
        web = os.path.join(ROOT, "web")
        # The page's files; web/report3d/ holds the report's 3-D view, built into the binary.
        for asset in sorted(a for a in os.listdir(web) if os.path.isfile(os.path.join(web, a))):
            status, _, body = s.request("GET", "/" + asset)
            check(status == 200 and len(body) > 100, "GET /%s" % asset)
            # Works offline: nothing fetched from elsewhere (the SVG namespace is a name, not a fetch).
            check(not re.search(rb"https?://|//cdn", body.replace(b"http://www.w3.org/2000/svg", b"")),
                  "/%s refers to no other host" % asset)
        status, _, info = s.json("GET", "/api/info")
        check(status == 200 and info.get("max_solves") == 2 and info.get("max_body") == 1 << 20,
              "GET /api/info: %s" % info)
        check(info.get("robot_defaults", {}).get("dof") == [2, 3] and info["robot_defaults"].get("max_link_length") == 1.0,
              "GET /api/info names the robot defaults: %s" % info)


def test_body_limit():
    with Server() as s:
        big = b'{"format": "modsynth-task/1", "pad": "' + b"x" * (1 << 20) + b'"}'
        try:
            status, _, body = s.json("POST", "/api/validate", big, JSON_TYPE)
        except OSError as e:  # the server may close while the rest is on its way
            status, body = None, {"error": str(e)}
        check(status == 413, "a body over 1 MB gets 413 (got %s)" % status)
        check("larger than" in body.get("error", ""), "413 says why: %s" % body)
        under = b'{"format": "modsynth-task/1", "pad": "' + b"x" * ((1 << 20) - 100) + b'"}'
        status, _, body = s.json("POST", "/api/validate", under, JSON_TYPE)
        check(status == 200 and body.get("valid") is False, "a body just under 1 MB is read (%s)" % status)
        check(s.alive(), "server alive after an oversized body")


def test_malformed_and_invalid():
    with Server() as s:
        status, _, body = s.json("POST", "/api/validate", b'{"format": "modsynth-task/1",', JSON_TYPE)
        check(status == 400 and "line 1, column" in body.get("error", ""),
              "malformed JSON: 400 naming line and column: %s" % body)
        status, _, body = s.json("POST", "/api/solve", b"\x00\xff garbage", JSON_TYPE)
        check(status == 400 and body.get("error"), "malformed JSON to /api/solve: 400 with a message")
        status, _, body = s.json("POST", "/api/validate", read(DISCONNECTED), JSON_TYPE)
        errors = body.get("errors") or [{}]
        check(status == 200 and body.get("valid") is False and errors[0].get("part") == "trajectory[1]",
              "validate names the offending part: %s" % body)
        status, _, body = s.json("POST", "/api/solve", read(DISCONNECTED), JSON_TYPE)
        check(status == 422 and body.get("part") == "trajectory[1]", "an invalid task to solve: 422 with its part")
        status, _, body = s.json("POST", "/api/validate", read(ROSE), JSON_TYPE)
        check(status == 200 and body.get("valid") is True and body.get("primitives") == 7, "rose is valid")
        # A spatial task is validated; an invalid one is refused naming its part.
        spatial = read(SPATIAL)
        status, _, body = s.json("POST", "/api/validate", spatial, JSON_TYPE)
        check(status == 200 and body.get("valid") is True and body.get("primitives") == 1,
              "a spatial task is valid: %s" % body)
        bad = json.loads(spatial)
        bad["obstacles"][0]["max"][2] = bad["obstacles"][0]["min"][2] - 0.1
        status, _, body = s.json("POST", "/api/solve", json.dumps(bad).encode(), JSON_TYPE)
        check(status == 422 and body.get("part") == "obstacles[0].max",
              "an invalid spatial task to solve: 422 with its part: %s" % body)
        status, _, body = s.json("POST", "/api/validate", b"{}", {"Content-Type": "text/plain"})
        check(status == 415, "a body that is not application/json: 415 (%s)" % status)
        status, _, body = s.json("GET", "/api/info", headers={"Host": "attacker.example"})
        check(status == 403, "a foreign Host name: 403 (%s)" % status)
        status, _, body = s.json("GET", "/api/nothing-here")
        check(status == 404 and body.get("error"), "unknown path: 404 with a JSON message")
        status, _, body = s.json("GET", "/api/jobs/0123456789abcdef")
        check(status == 404, "unknown job: 404")
        status, _, body = s.solve(ROSE, "?time_limit=soon")
        check(status == 400 and body.get("part") == "time_limit", "bad time_limit: 400 naming it")


def test_solve_and_files():
    with Server() as s:
        status, headers, job = s.solve(ROSE)
        check(status == 202 and job.get("id") and headers.get("Location") == job["links"]["self"],
              "POST /api/solve: 202 with the job")
        job = s.wait(job["id"], done, 60)
        check(job.get("status") == "solved", "rose solved through the API: %s" % job.get("status"))
        result = job.get("result") or {}
        check(result.get("dof") in (2, 3) and result.get("total_link_length", 0) > 0, "result figures")
        check(any(line.startswith("[") for line in job.get("log", [])), "progress lines were followed")
        for name, marker in [("solution.json", b'"status": "solved"'), ("report.html", b'<svg id="plot"'),
                             ("robot.urdf", b"<robot"), ("trajectory.csv", b"t,q1,q2"),
                             ("joint-trajectory.yaml", b"joint_names:"),
                             ("build-sheet.md", b"#")]:
            url = job.get("files", {}).get(name)
            status, headers, body = s.request("GET", url or "/missing")
            check(status == 200 and marker in body, "download %s" % name)
        status, _, log = s.request("GET", job.get("files", {}).get("solve.log", "/missing"))
        check(status == 200 and log.strip(), "download solve.log")
        check(b"modsynth-serve" not in log and tempfile.gettempdir().encode() + b"/" not in log,
              "solve.log does not tell the server's scratch folder: %r" % log[:300])
        status, headers, _ = s.request("GET", job["files"]["robot.urdf"] + "?download=1")
        check("attachment" in headers.get("Content-Disposition", ""), "?download=1 sends an attachment")
        status, _, _ = s.request("GET", "/api/jobs/%s/files/..%%2F..%%2Fetc%%2Fpasswd" % job["id"])
        check(status == 404, "only the job's own files are served")


def test_spatial_solve_and_files():
    with Server() as s:
        status, _, job = s.solve(SPATIAL)
        check(status == 202 and job.get("id"), "POST /api/solve of a spatial task: 202 with the job")
        job = s.wait(job["id"], done, 60)
        check(job.get("status") == "solved", "s3-0001 solved through the API: %s" % job.get("status"))
        result = job.get("result") or {}
        check(result.get("name") == "s3-0001" and result.get("dof") == 3 and
              result.get("total_link_length", 0) > 0, "spatial result figures: %s" % result)
        check(any("joints: front stage" in line for line in job.get("log", [])),
              "the spatial progress was followed")
        # The files `modsynth solve` writes for a spatial solution.
        for name, marker in [("solution.json", b'"dh"'), ("report.html", b'id="scene-data"'),
                             ("robot.urdf", b"<robot"), ("trajectory.csv", b"t,q1,q2,q3"),
                             ("joint-trajectory.yaml", b"joint_names:"),
                             ("build-sheet.md", b"A spatial arm")]:
            url = job.get("files", {}).get(name)
            status, headers, body = s.request("GET", url or "/missing")
            check(status == 200 and marker in body, "download the spatial %s" % name)
        # Out of reach: the planted core, then explain's changes.
        job = s.solve(SPATIAL_OUT_OF_REACH)[2]
        job = s.wait(job["id"], done, 90)
        result = job.get("result") or {}
        check(result.get("status") == "infeasible" and
              {"robot.max_link_length", "base_regions", "trajectory[0]"} <= set(result.get("core", [])),
              "sir-0001 infeasible with its planted core: %s" % result)
        explanation = job.get("explanation") or {}
        parts = {x.get("part") for x in explanation.get("suggestions", [])}
        check(job.get("status") == "infeasible" and "robot.max_link_length" in parts,
              "spatial suggested changes: %s %s" % (explanation, job.get("explanation_note")))


def test_infeasible_explained():
    with Server() as s:
        job = s.solve(OUT_OF_REACH)[2]
        job = s.wait(job["id"], lambda j: j.get("result") is not None, 30)
        check((job.get("result") or {}).get("status") == "infeasible", "out-of-reach is infeasible")
        check("trajectory[0]" in (job.get("result") or {}).get("core", []), "its core names trajectory[0]")
        job = s.wait(job["id"], done, 90)
        suggestions = (job.get("explanation") or {}).get("suggestions")
        check(job.get("status") == "infeasible" and (suggestions or job.get("explanation_note")),
              "suggested changes (or why there are none): %s" % job.get("explanation_note"))


def test_concurrency_limit_and_cancel():
    with Server("--max-solves", "1") as s:
        first = s.solve(SLOW, "?time_limit=30")[2]
        job = s.wait(first["id"], running_with_progress, 10)
        check(not done(job), "precondition: the slow task is still running (%s)" % job.get("status"))
        status, headers, body = s.solve(ROSE)
        check(status == 429 and headers.get("Retry-After") and body.get("error"),
              "beyond --max-solves: 429 with Retry-After (%s)" % status)
        check(len(s.children()) == 1, "one solve process runs")
        started = time.monotonic()
        status, _, job = s.json("POST", job["links"]["cancel"])
        check(status == 200 and job.get("status") == "cancelled", "cancel answers with the cancelled job")
        check(time.monotonic() - started < 2, "cancel is immediate")
        check(s.children() == [], "the cancelled solve's process is gone")
        status, _, second = s.solve(ROSE)
        check(status == 202, "a freed slot takes the next solve (%s)" % status)
        s.wait(second.get("id", ""), done, 60)
        status, _, job = s.json("POST", first["links"]["cancel"])
        check(status == 200 and job.get("status") == "cancelled", "cancelling a finished job changes nothing")


def test_time_limit():
    with Server("--time-limit", "1", "--grace", "0.5") as s:
        started = time.monotonic()
        job = s.solve(SLOW, "?time_limit=100")[2]
        check(job.get("time_limit") == 1, "a request cannot raise the server's time limit")
        job = s.wait(job["id"], done, 10)
        took = time.monotonic() - started
        check(job.get("status") in ("unknown", "timeout"), "a solve past its limit stops: %s" % job.get("status"))
        check(took < 1 + 0.5 + 1.5, "... within the limit and grace (%.2f s)" % took)
    with Server("--grace", "0") as s:
        job = s.solve(SLOW, "?time_limit=0.3")[2]
        job = s.wait(job["id"], done, 5)
        check(done(job) and job.get("elapsed", 99) < 1.5,
              "a request's own shorter limit holds (%s after %s s)" % (job.get("status"), job.get("elapsed")))


def test_client_that_leaves():
    with Server("--client-timeout", "1") as s:
        job = s.solve(SLOW, "?time_limit=30")[2]
        time.sleep(2.5)  # ask nothing: the client is gone
        job = s.job(job["id"])
        check(job.get("status") == "cancelled" and "client left" in job.get("cancel_reason", ""),
              "a solve nobody asks about is cancelled: %s / %s" % (job.get("status"), job.get("cancel_reason")))
        check(s.children() == [], "... and its process is gone")
    with Server() as s:
        job = s.solve(SLOW, "?time_limit=30")[2]
        sock = socket.create_connection(("127.0.0.1", s.port), timeout=5)
        sock.sendall(("GET %s HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n" % job["links"]["events"]).encode())
        first = sock.recv(4096)
        check(b"text/event-stream" in first, "the progress stream opens")
        sock.close()
        job = s.wait(job["id"], done, 5)
        check(job.get("status") == "cancelled" and "stream closed" in job.get("cancel_reason", ""),
              "closing the progress stream cancels: %s" % job.get("cancel_reason"))


def test_long_poll():
    with Server() as s:
        job = s.solve(SLOW, "?time_limit=30")[2]
        started = time.monotonic()
        status, _, later = s.json("GET", "/api/jobs/%s?since=%d&wait=5" % (job["id"], job["version"]))
        check(status == 200 and later.get("version", 0) > job["version"] and time.monotonic() - started < 5,
              "a long poll answers at the next change")
        status, _, _ = s.json("GET", "/api/jobs/%s?since=0&wait=-1" % job["id"])
        check(status == 400, "a bad wait is 400")
        s.json("POST", job["links"]["cancel"])


def test_garbage_does_not_kill():
    with Server() as s:
        junk = [b"\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03" + os.urandom(64),  # a TLS hello
                b"NOT A REQUEST\r\n\r\n",
                b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: -5\r\n\r\n",
                b"POST /api/solve HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                b"Content-Length: 1000\r\n\r\n{\"format\":",  # then hang up mid-body
                b"GET /" + b"a" * 20000 + b" HTTP/1.1\r\n\r\n",
                b"GET / HTTP/1.1\r\n" + b"X: y\r\n" * 5000 + b"\r\n",
                os.urandom(3000)]
        for data in junk:
            try:
                sock = socket.create_connection(("127.0.0.1", s.port), timeout=3)
                sock.sendall(data)
                sock.shutdown(socket.SHUT_WR)
                sock.recv(1024)
            except OSError:
                pass
            finally:
                sock.close()
        status, _, body = s.json("POST", "/api/solve", b'{"format": "modsynth-task/1", "trajectory": 7}', JSON_TYPE)
        check(status == 422, "a task of the wrong shape: 422 (%s)" % status)
        check(s.alive(), "garbage requests do not kill the server")


def json_error(body):
    """The message of a JSON error body, or None when it is not one."""
    try:
        return json.loads(body.decode("utf-8")).get("error")
    except (ValueError, UnicodeDecodeError, AttributeError):
        return None


def test_invalid_utf8():
    with Server() as s:
        for path in [b"/%ff", b"/%c3%28", b"/api/%ed%a0%80", b"/api/jobs/0123456789abcdef?since=1&wait=%ff"]:
            status, body = s.raw(b"GET " + path + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
            check(status is not None and 400 <= status < 500, "GET %s: a 4xx (%s)" % (path, status))
            check(json_error(body), "GET %s: a JSON error in UTF-8: %r" % (path, body[:200]))
            check(s.alive(), "the server survives GET %s" % path)
        for route in ["/api/validate", "/api/solve"]:
            status, _, body = s.request("POST", route, b'{"format": "modsynth-task/1", "name": "\xff\xfe', JSON_TYPE)
            check(status == 400, "invalid UTF-8 in a body to %s: 400 (%s)" % (route, status))
            check(json_error(body), "... with a JSON error in UTF-8: %r" % body[:200])
        status, _, body = s.request("POST", "/api/validate", b'{"format": "\xc0\xaf"}', JSON_TYPE)
        check(status == 400 and json_error(body), "an overlong UTF-8 form: 400 (%s) %r" % (status, body[:200]))
        check(s.alive(), "server alive after invalid UTF-8")


def test_chunked_body_limit():
    with Server() as s:
        head = (b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                b"Transfer-Encoding: chunked\r\n\r\n")
        chunk = b"10000\r\n" + b" " * 0x10000 + b"\r\n"
        status = None
        with socket.create_connection(("127.0.0.1", s.port), timeout=3) as sock:
            try:
                sock.sendall(head + chunk * 32)  # 2 MB, and no last chunk: the body never ends
                reply = sock.recv(4096)
                m = re.match(rb"HTTP/1\.1 (\d{3}) ", reply)
                status = int(m.group(1)) if m else reply[:100]
            except OSError as e:
                status = repr(e)
        check(status == 413, "a chunked body over 1 MB: 413 before the body ends (%s)" % status)
        with socket.create_connection(("127.0.0.1", s.port), timeout=3) as sock:
            try:
                sock.sendall(head.replace(b"/api/validate", b"/api/nothing") + chunk * 32)
                reply = sock.recv(4096)
                status = int(reply[9:12]) if reply.startswith(b"HTTP/1.1 ") else reply[:100]
            except OSError as e:
                status = repr(e)
        check(status == 404, "a chunked body to no route: 404 before the body ends (%s)" % status)
        rose = read(ROSE)
        chunks = b"".join(b"%x\r\n%s\r\n" % (len(rose[i:i + 500]), rose[i:i + 500]) for i in range(0, len(rose), 500))
        status, body = s.raw(head + chunks + b"0\r\n\r\n")
        check(status == 200 and b'"valid": true' in body, "a chunked body under the limit is read (%s)" % status)
        check(s.alive(), "server alive after a chunked body over the limit")


def test_host_rule():
    with Server() as s:
        for host in ["127.attacker.example", "127.0.0.1.attacker.example", "localhost.attacker.example",
                     "127.256.0.1", "127.0.0.1:%d" % (s.port + 1), "[::1].attacker.example", "127.0.0.1:"]:
            status, _, body = s.json("GET", "/api/info", headers={"Host": host})
            check(status == 403 and body.get("error"), "Host: %s is refused with 403 (%s)" % (host, status))
        for host in ["127.0.0.1", "127.0.0.1:%d" % s.port, "localhost:%d" % s.port, "LOCALHOST",
                     "[::1]:%d" % s.port, "127.1.2.3"]:
            status, _, _ = s.json("GET", "/api/info", headers={"Host": host})
            check(status == 200, "Host: %s is served (%s)" % (host, status))


def test_port_in_use():
    with Server() as s:
        second = subprocess.Popen([BIN, "serve", "--port", str(s.port)], stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True)
        try:
            out, err = second.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            second.kill()
            out, err = second.communicate()
            err = "still running: " + err
        check(second.returncode == 2 and ("port %d on 127.0.0.1 is in use" % s.port) in err,
              "a second server on a port in use exits 2 saying so (exit %s, %r)" % (second.returncode, err))
        check(s.alive(), "the first server still answers")


def test_media_type():
    with Server() as s:
        for media in ["APPLICATION/JSON", "application/json; charset=utf-8", "Application/Json;charset=UTF-8"]:
            status, _, body = s.json("POST", "/api/validate", read(ROSE), {"Content-Type": media})
            check(status == 200 and body.get("valid") is True, "Content-Type: %s is JSON (%s)" % (media, status))
        for media in ["application/jsonp", "text/plain; application/json"]:
            status, _, _ = s.json("POST", "/api/validate", read(ROSE), {"Content-Type": media})
            check(status == 415, "Content-Type: %s is not (%s)" % (media, status))


def test_whole_replies():
    with Server() as s:
        for path, asked in [("/api/nothing", {"Range": "bytes=0-3"}), ("/api/info", {"Range": "bytes=9999-"}),
                              ("/api/info", {"Range": "bytes=x"}), ("/app.js", {"Range": "bytes=0-9,20-29"})]:
            status, headers, body = s.request("GET", path, headers=asked)
            check(status in (200, 404, 416) and "Content-Range" not in headers and
                  (status == 200 or json_error(body)),
                  "GET %s with %s: the whole reply (%s %r)" % (path, asked, status, body[:80]))


def test_slow_clients():
    with Server() as s:
        job = s.solve(SLOW, "?time_limit=30")[2]
        slow, streams = [], []
        try:
            for _ in range(40):  # each sends half a head, then nothing
                sock = socket.create_connection(("127.0.0.1", s.port), timeout=5)
                sock.sendall(b"GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\n")
                slow.append(sock)
            opened = time.monotonic()
            for _ in range(25):
                sock = socket.create_connection(("127.0.0.1", s.port), timeout=5)
                sock.sendall(("GET %s HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n" % job["links"]["events"]).encode())
                streams.append(sock)
            started = time.monotonic()
            status, _, info = s.json("GET", "/api/info")
            took = time.monotonic() - started
            check(status == 200 and took < 2, "/api/info answers beside slow clients and open streams "
                                              "(%s after %.2f s)" % (status, took))
            firsts = []
            for sock in streams:
                try:
                    firsts.append(sock.recv(4096))
                except OSError:
                    firsts.append(b"")
            opened_streams = sum(b"text/event-stream" in f for f in firsts)
            refused = sum(f.startswith(b"HTTP/1.1 429") for f in firsts)
            check(1 <= opened_streams <= 4 and opened_streams + refused == 25,
                  "progress streams are capped per client: %d open, %d refused" % (opened_streams, refused))
            time.sleep(max(0.0, opened + 6 - time.monotonic()))
            slow[0].settimeout(3)
            reply = slow[0].recv(4096)
            check(reply.startswith(b"HTTP/1.1 408") and json_error(reply.partition(b"\r\n\r\n")[2]),
                  "a head that does not come in time: 408 (%r)" % reply[:80])
        finally:
            for sock in slow + streams:
                sock.close()
        check(s.alive(), "server alive after slow clients")


def test_solves_hold_no_sockets():
    """A solve must not inherit the server's sockets: a connection it held
    would not close for its client until the solve ended, and a listening
    socket would keep the port."""
    with Server() as s:
        with socket.create_connection(("127.0.0.1", s.port), timeout=10) as sock:
            body = read(SLOW)
            sock.sendall(b"POST /api/solve?time_limit=30 HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                         b"Content-Type: application/json\r\nContent-Length: %d\r\n\r\n" % len(body) + body)
            reply = sock.recv(65536)
            check(reply.startswith(b"HTTP/1.1 202"), "a solve starts on a kept-alive connection (%r)" % reply[:40])
            deadline = time.monotonic() + 5
            kids = s.children()
            while not kids and time.monotonic() < deadline:
                time.sleep(0.05)
                kids = s.children()
            check(len(kids) == 1, "the solve runs as a child (%d)" % len(kids))
            # Between fork and exec the child is still a copy of the server and
            # holds its descriptors; what matters is the solve the exec starts.
            deadline = time.monotonic() + 5
            while kids and not all(s.execed_solve(k) for k in kids) and time.monotonic() < deadline:
                time.sleep(0.02)
            check(all(s.execed_solve(k) for k in kids), "the child has become a solve")
            sockets = []
            for kid in kids:
                try:
                    for fd in os.listdir("/proc/%d/fd" % kid):
                        target = os.readlink("/proc/%d/fd/%s" % (kid, fd))
                        if target.startswith("socket:"):
                            sockets.append(target)
                except OSError:
                    pass
            check(not sockets, "the solve holds none of the server's sockets (%s)" % sockets)


def test_shutdown_kills_solves():
    s = Server()
    job = s.solve(SLOW, "?time_limit=30")[2]
    s.wait(job["id"], running_with_progress, 10)
    kids = s.children()
    check(len(kids) == 1, "a solve runs before the shutdown")
    code = s.stop()
    check(code == 0, "SIGTERM stops the server cleanly (exit %s)" % code)
    time.sleep(0.2)
    check(all(not os.path.exists("/proc/%d" % k) for k in kids), "no solve outlives the server")


def test_import_drawing():
    """POST /api/import: a drawing's bytes to the task `modsynth import` writes, with the
    map that puts the file's page under it; a bad file is a 4xx naming its element."""
    sketch = os.path.join(ROOT, "tasks/drawings/sketch.svg")
    svg_type = {"Content-Type": "image/svg+xml"}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "cli.json")
        subprocess.run([BIN, "import", sketch, "-o", out, "--at", "0.3,0.1", "--tolerance", "0.001"],
                       check=True, stdout=subprocess.DEVNULL)
        cli = json.load(open(out))
    with Server() as s:
        status, _, body = s.json("POST", "/api/import?format=svg&at=0.3,0.1&tolerance=0.001&name=sketch",
                                 read(sketch), svg_type)
        check(status == 200 and body.get("task") == cli,
              "the task is the one `modsynth import` writes with the same options (%s)" % status)
        n = sum(len(stroke) for stroke in cli.get("strokes", [cli.get("trajectory")]))
        check(body.get("primitives") == n and body.get("strokes") == len(cli.get("strokes", [0])),
              "counts of primitives and strokes: %s %s" % (body.get("primitives"), body.get("strokes")))
        check(0 < body.get("deviation", 0) <= 0.001 and body.get("tolerance") == 0.001,
              "the deviation reached is within the tolerance: %s" % body.get("deviation"))
        u = body.get("underlay") or {}
        # The page is 200 x 150 mm at 96 px per inch; the map is a scale of
        # 1 mm per unit with y flipped, so (20, 40) mm on the page, the wave's
        # first point, lands on a vertex of the fitted path.
        check(abs(u.get("width", 0) - 200 / 25.4 * 96) < 1e-6 and abs(u.get("height", 0) - 150 / 25.4 * 96) < 1e-6
              and u.get("y_flip") is True, "the underlay's page size and flip: %s" % u)
        a, b, c, d, e, f = u.get("transform", [0] * 6)
        px = (20 / 25.4 * 96, 40 / 25.4 * 96)
        wave = (a * px[0] + c * px[1] + e, b * px[0] + d * px[1] + f)
        ends = [p[k] for stroke in cli["strokes"] for p in stroke for k in ("start", "end") if k in p]
        check(any(abs(q[0] - wave[0]) < 1e-6 and abs(q[1] - wave[1]) < 1e-6 for q in ends),
              "the underlay's map puts the wave's start on the path: %s" % (wave,))
        check(body.get("placement", {}).get("metres_per_unit") == 0.001, "placement: %s" % body.get("placement"))

        # On a surface in space, in a child `modsynth import` as on the command line.
        bracket = os.path.join(ROOT, "tasks/drawings/bracket.dxf")
        for option, numbers, kind in [("--plane", "0.4,0,0.25,0,-1,0,0,0,1", "plane"),
                                      ("--cylinder", "0.4,0,0.25,0,0,1,0.08", "cylinder")]:
            with tempfile.TemporaryDirectory() as tmp:
                out = os.path.join(tmp, "cli.json")
                subprocess.run([BIN, "import", bracket, "-o", out, "--name", "bracket",
                                option, numbers, "--base", "-0.05,-0.05,0.02,0.05,0.05,0.02"],
                               check=True, stdout=subprocess.DEVNULL)
                cli = json.load(open(out))
            status, _, body = s.json("POST", "/api/import?format=dxf&name=bracket&%s=%s&base=-0.05,-0.05,0.02,0.05,0.05,0.02"
                                     % (kind, numbers), read(bracket), {"Content-Type": "application/dxf"})
            check(status == 200 and body.get("surface") == kind and body.get("underlay") is None
                  and body.get("deviation", 1) <= 1e-4 and body.get("tolerance") == 1e-4,
                  "%s: a spatial task (%s %s)" % (kind, status, body.get("error")))
            check(body.get("task") == cli and cli.get("space") == "3d",
                  "%s: the task is the one `modsynth import %s` writes" % (kind, option))
        status, _, body = s.json("POST", "/api/import?format=dxf&plane=0,0,0,1,0,0,1,0,0", read(bracket),
                                 {"Content-Type": "application/dxf"})
        check(status == 400 and body.get("part") == "plane", "a plane whose U and V are one: 400 naming plane (%s)" % body)
        status, _, body = s.json("POST", "/api/import?format=dxf&cylinder=0,0,0,0,0,1,0.001&base=-1,-1,0,1,1,0", read(bracket),
                                 {"Content-Type": "application/dxf"})
        check(status == 422 and body.get("part") == "cylinder" and "circumference" in body.get("error", ""),
              "a drawing wider than the cylinder, from the child: 422 naming cylinder (%s)" % body)
        # A line nearly along the axis, turned a hundredth of a degree: its
        # chord, never a refusal naming a helix pitch the client never wrote.
        axial = (b'<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">'
                 b'<line x1="50" y1="10" x2="50" y2="90" stroke="black"/>'
                 b'<line x1="20" y1="50" x2="80" y2="60" stroke="black"/></svg>')
        status, _, body = s.json("POST", "/api/import?format=svg&cylinder=0,0,0,0,0,1,0.1&rotate=0.01", axial, svg_type)
        check(status == 200 and body.get("surface") == "cylinder",
              "a nearly axial line round a cylinder imports (%s %s)" % (status, body.get("error")))

        status, _, body = s.json("POST", "/api/import?format=dxf", read(os.path.join(ROOT, "tasks/drawings/bracket.dxf")),
                                 {"Content-Type": "application/dxf"})
        check(status == 200 and body.get("underlay") is None and body.get("primitives", 0) > 0,
              "a DXF imports, with no page to show (%s %s)" % (status, body.get("error")))
        # The layers found, with their entity counts, as the CLI prints them.
        check(body.get("layers") == {"0": 5, "keepout": 1, "outline": 1} and body.get("warnings") == [],
              "the DXF's layers and entity counts, no warning: %s %s" % (body.get("layers"), body.get("warnings")))
        # What is skipped is said, as the CLI says it on standard error.
        dotted = (b'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24"><path d="M2 2h20"/>'
                  b'<path id="dot" d="M12 8l0 0"/><path d="M2 20h20"/></svg>')
        status, _, body = s.json("POST", "/api/import?format=svg&width=0.1", dotted, svg_type)
        warnings = body.get("warnings") or [""]
        check(status == 200 and len(warnings) == 1 and "skipped dots" in warnings[0] and "path#dot" in warnings[0]
              and body.get("layers") == {} and body.get("filled_outlines") == 2,
              "the warnings of a drawing with a dot, and its filled outlines: %s %s" % (status, body))
        bad = b'<svg xmlns="http://www.w3.org/2000/svg"><path id="p3" d="M 10,10 L 20"/></svg>'
        status, _, body = s.json("POST", "/api/import?format=svg", bad, svg_type)
        check(status == 422 and "path#p3" in body.get("error", "") and "path#p3" in body.get("part", ""),
              "a malformed path: 422 naming the element: %s" % body)
        for garbage in [b"", b"\x00\xff<svg", b"<svg", b"not xml at all", b"<html/>", b"0\nSECTION\n"]:
            status, _, body = s.json("POST", "/api/import?format=svg", garbage, svg_type)
            check(status == 422 and body.get("error"), "garbage %r: 422 with a message (%s)" % (garbage[:12], status))
        for query, part in [("format=png", "format"), ("format=svg&width=-1", "width"),
                            ("format=svg&at=1", "at"), ("format=svg&at=1,x", "at"),
                            ("format=svg&tolerance=5", "tolerance"), ("format=svg&width=1&scale=1", "scale"),
                            ("format=svg&rotate=1e9", "rotate"),
                            # Numbers as people write them, a parameter once.
                            ("format=svg&width=0x10", "width"), ("format=svg&at=0x1,0", "at"),
                            ("format=svg&width=inf", "width"), ("format=svg&width=%200.1", "width"),
                            ("format=svg&format=dxf", "format"), ("format=svg&width=0.1&width=0.2", "width")]:
            status, _, body = s.json("POST", "/api/import?" + query, read(sketch), svg_type)
            check(status == 400 and body.get("part") == part, "%s: 400 naming %s (%s %s)" % (query, part, status, body))
        status, _, body = s.json("POST", "/api/import?format=svg", read(sketch), {"Content-Type": "text/plain"})
        check(status == 415, "a drawing sent as text/plain (what a cross-site form can send): 415 (%s)" % status)
        status, _, body = s.json("POST", "/api/import?format=svg", read(sketch), JSON_TYPE)
        check(status == 415, "a drawing sent as JSON: 415 (%s)" % status)
        big = b"<svg>" + b" " * (1 << 20) + b"</svg>"
        try:
            status, _, body = s.json("POST", "/api/import?format=svg", big, svg_type)
        except OSError as e:
            status, body = None, {"error": str(e)}
        check(status == 413, "a drawing over 1 MB: 413 (%s)" % status)
        check(s.alive(), "server alive after bad drawings")


def coil_task(posts):
    """A helix of a thousand turns round posts that nearly touch it all along:
    checking it takes tens of milliseconds per post."""
    return json.dumps({
        "format": "modsynth-task/1", "name": "coil", "space": "3d",
        "trajectory": [{"type": "helix", "start": [0.12, 0, 0.1], "center": [0, 0, 0.1], "axis": [0, 0, 1],
                        "direction": "ccw", "pitch": 0.005, "turns": 1000}],
        "obstacles": [{"type": "capsule", "a": [0, 0, 0], "b": [0, 0, 5.2], "radius": round(0.1199 - 1e-6 * i, 7)}
                      for i in range(posts)],
        "base_regions": [{"min": [-0.05, -0.05, -0.9], "max": [0.05, 0.05, -0.9]}]}).encode()


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def test_spatial_checks_bounded():
    """A task that takes minutes to check holds a worker at most a few seconds,
    whether its client waits or leaves; a solve of it goes to a job, which
    checks it within its own time limit."""
    body = coil_task(1000)
    with Server() as s:
        start = time.monotonic()
        status, _, reply = s.json("POST", "/api/validate", body, JSON_TYPE)
        took = time.monotonic() - start
        check(status == 200 and reply.get("checked") is False and not reply.get("valid")
              and "time limit" in json.dumps(reply.get("errors")),
              "validate of a coil says it was not checked: %s %s" % (status, reply))
        check(took < 8, "validate of a coil answered in %.1f s" % took)
        # Clients that send it and leave: the server's CPU stops soon after.
        for _ in range(3):
            sock = socket.create_connection(("127.0.0.1", s.port), timeout=5)
            sock.sendall(b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                         b"Content-Length: %d\r\n\r\n" % len(body) + body)
            time.sleep(0.2)
            sock.close()
        time.sleep(7)
        before = cpu_seconds(s.proc.pid)
        time.sleep(5)
        spent = cpu_seconds(s.proc.pid) - before
        check(spent < 1.0, "the server kept checking a coil after its clients left: %.1f s of CPU" % spent)
        status, _, reply = s.json("POST", "/api/solve?time_limit=3", body, JSON_TYPE)
        check(status == 202, "a coil to solve becomes a job: %s %s" % (status, reply))
        if status == 202:
            # Reading the outcome needs the task's name, not its checks: the
            # job ends soon after its child, and the jobs API answers all along.
            start = time.monotonic()
            job = s.wait(reply["id"], done, 20)
            took = time.monotonic() - start
            check(job and job.get("status") == "unknown", "the coil's job answers unknown: %s" % job)
            check(took < 15, "the coil's job ended %.1f s after it was sent (a 3 s limit)" % took)
        check(s.alive(), "server alive after coils")


def hostile_dxf(n):
    """About 2 KB that once pinned an import for ever: a line longer than the
    DXF library's buffer (then 1-3: a count written with a leading zero, a
    spline of 1e-160 mm, a file cut off)."""
    head = "0\nSECTION\n2\nENTITIES\n"
    if n % 4 == 0:
        return (head + "0\nLINE\n8\n" + "L" * 2000 + "\n10\n0\n20\n0\n11\n1\n21\n0\n0\nENDSEC\n0\nEOF\n").encode()
    if n % 4 == 1:
        return (head + "0\nLWPOLYLINE\n8\n0\n090\n200000000\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n" +
                "999\n" + "x" * 1900 + "\n").encode()
    if n % 4 == 2:
        return (head + "0\nSPLINE\n8\n0\n71\n3\n72\n8\n73\n4\n" +
                "".join("40\n%d\n" % k for k in (0, 0, 0, 0, 1, 1, 1, 1)) +
                "".join("10\n%s\n20\n%s\n" % p for p in (("0", "0"), ("1e-160", "2e-160"),
                                                          ("2e-160", "-1e-160"), ("3e-160", "0"))) +
                "0\nENDSEC\n0\nEOF\n" + "999\n" + "x" * 1700 + "\n").encode()
    return (head + ("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n" * 60))[:2000].encode()


def test_hostile_imports_and_slow_bodies():
    """Imports run where they can be bounded and killed, and bodies are
    waited for without a worker: 24 hostile imports and 60 connections that
    send a head promising a megabyte and then one byte leave /api/info
    answering within 2 s, and the server stops within 5 s of SIGTERM."""
    import threading
    s = Server()
    slow, replies = [], []
    try:
        for _ in range(60):
            sock = socket.create_connection(("127.0.0.1", s.port), timeout=15)
            sock.sendall(b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                         b"Content-Type: application/json\r\nContent-Length: 1000000\r\n\r\n{")
            slow.append(sock)
        opened = time.monotonic()

        def hostile_import(n):
            try:
                status, _, body = s.json("POST", "/api/import?format=dxf&scale=0.001", hostile_dxf(n),
                                         {"Content-Type": "application/dxf"})
                replies.append((status, body.get("error", "")))
            except Exception as e:  # a hang or a broken connection is a failure
                replies.append((None, repr(e)))
        threads = [threading.Thread(target=hostile_import, args=(n,)) for n in range(24)]
        for t in threads:
            t.start()
        started = time.monotonic()
        status, _, info = s.json("GET", "/api/info")
        took = time.monotonic() - started
        check(status == 200 and took < 2, "/api/info answers beside 24 hostile imports and 60 slow "
                                          "bodies (%s after %.2f s)" % (status, took))
        started = time.monotonic()
        status, _, body = s.json("POST", "/api/validate", read(ROSE), JSON_TYPE)
        took = time.monotonic() - started
        check(status == 200 and body.get("valid") is True and took < 2,
              "a whole request is answered beside them (%s after %.2f s)" % (status, took))
        for t in threads:
            t.join(20)
        failed = [e for st, e in replies if st not in (422, 429)]
        check(len(replies) == 24 and not failed,
              "every hostile import is refused or asked to wait: %s%s" %
              (sorted(set(str(r[0]) for r in replies)),
               " (%d replied; failed: %s)" % (len(replies), failed[:4]) if failed or len(replies) != 24 else ""))
        named = [e for st, e in replies if st == 422]
        check(named and all("line" in e or "across" in e or "declares" in e or "cut off" in e for e in named),
              "a refused import says why: %s" % named[:4])
        # A body that does not come in time is answered 408, from the room.
        time.sleep(max(0.0, opened + 11 - time.monotonic()))
        slow[0].settimeout(3)
        reply = slow[0].recv(4096)
        check(reply.startswith(b"HTTP/1.1 408") and json_error(reply.partition(b"\r\n\r\n")[2]),
              "a body that does not come in time: 408 (%r)" % reply[:80])
        # The rest are open still: the stop must not wait for them.
        for _ in range(60):
            sock = socket.create_connection(("127.0.0.1", s.port), timeout=15)
            sock.sendall(b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\n"
                         b"Content-Type: application/json\r\nContent-Length: 1000000\r\n\r\n{")
            slow.append(sock)
        for n in range(4):
            threading.Thread(target=hostile_import, args=(n,), daemon=True).start()
        stopping = time.monotonic()
        s.proc.send_signal(signal.SIGTERM)
        try:
            code = s.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            code = None
        took = time.monotonic() - stopping
        check(code == 0 and took < 5, "SIGTERM stops the server within 5 s (exit %s after %.2f s)" % (code, took))
    finally:
        for sock in slow:
            sock.close()
        s.stop()


def test_connection_burst():
    """200 connections opened at once, each with a whole request, are all
    answered: the listen queue takes the burst rather than leaving it to
    SYN cookies, which reset some connections the client thinks open."""
    with Server() as s:
        socks = []
        for _ in range(200):
            sock = socket.socket()
            sock.setblocking(False)
            sock.connect_ex(("127.0.0.1", s.port))
            socks.append(sock)
        statuses = []
        try:
            for sock in socks:
                sock.setblocking(True)
                sock.settimeout(20)
                try:
                    sock.sendall(b"GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
                    reply = b""
                    while len(reply) < 12:
                        chunk = sock.recv(4096)
                        if not chunk:
                            break
                        reply += chunk
                    statuses.append(reply[9:12].decode(errors="replace") or "closed")
                except OSError as e:
                    statuses.append(type(e).__name__)
        finally:
            for sock in socks:
                sock.close()
        counts = {k: statuses.count(k) for k in sorted(set(statuses))}
        check(counts == {"200": 200}, "a burst of 200 connections is answered on each: %s" % counts)


def test_slow_body_keeps_alive():
    """A body sent in pieces, slower than a worker would wait between reads
    but within the body's deadline, is read whole; a chunked one too; and a
    pipelined request after it is answered on the same connection."""
    with Server() as s:
        body = read(ROSE)
        with socket.create_connection(("127.0.0.1", s.port), timeout=15) as sock:
            sock.sendall(b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                         b"Expect: 100-continue\r\nContent-Length: %d\r\n\r\n" % len(body))
            cont = sock.recv(4096)
            check(cont.startswith(b"HTTP/1.1 100"), "Expect: 100-continue is answered at once (%r)" % cont[:40])
            for i in range(0, len(body), len(body) // 3 + 1):
                sock.sendall(body[i:i + len(body) // 3 + 1])
                time.sleep(0.3)
            chunked = b"".join(b"%x\r\n%s\r\n" % (len(body[i:i + 100]), body[i:i + 100])
                               for i in range(0, len(body), 100)) + b"0\r\n\r\n"
            sock.sendall(b"POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                         b"Transfer-Encoding: chunked\r\n\r\n" + chunked +
                         b"GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
            reply = b""
            while True:
                chunk = sock.recv(65536)
                if not chunk:
                    break
                reply += chunk
        statuses = re.findall(rb"HTTP/1\.1 (\d{3}) ", reply)
        check(statuses == [b"200", b"200", b"200"] and reply.count(b'"valid": true') == 2,
              "a slow body, a chunked one and a pipelined request: %r" % statuses)


def main():
    tests = [test_page_and_info, test_body_limit, test_malformed_and_invalid, test_solve_and_files,
             test_spatial_solve_and_files, test_infeasible_explained, test_concurrency_limit_and_cancel, test_time_limit,
             test_client_that_leaves, test_long_poll, test_garbage_does_not_kill, test_invalid_utf8,
             test_chunked_body_limit, test_host_rule, test_port_in_use, test_media_type,
             test_whole_replies, test_slow_clients, test_solves_hold_no_sockets,
             test_shutdown_kills_solves, test_import_drawing, test_hostile_imports_and_slow_bodies,
             test_slow_body_keeps_alive, test_connection_burst, test_spatial_checks_bounded]
    for t in tests:
        started = time.monotonic()
        try:
            t()
        except Exception as e:  # one broken check must not hide the others
            failures.append("%s raised %r" % (t.__name__, e))
            print("FAIL: %s raised %r" % (t.__name__, e), flush=True)
        print("%-36s %.1f s" % (t.__name__, time.monotonic() - started), flush=True)
    if failures:
        print("serve: %d of %d checks failed" % (len(failures), checks))
        return 1
    print("serve: all %d checks passed" % checks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
