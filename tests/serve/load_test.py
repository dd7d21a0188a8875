#!/usr/bin/env python3
"""`penumbra serve` under load on loopback (docs/reliability.md, "The server under load").

Starts the server on fixtures/scenes/serve-room.json and, for a bounded time, runs:
  - clients that change lamps (colour, dimming, aim, a control point; half of them asking
    for the relit answer), fetch the relit values, the lamps and lux at patches;
  - malformed requests: bodies that are not JSON or hold wrong values, unknown lights and
    paths, wrong methods, paths that climb out of the page, bodies over the server's limit,
    garbage bytes, requests cut off in the middle;
  - slow clients that send a request one byte at a time;
and, before that, one request on a new connection while 16 idle keep-alive connections are
open, which must be answered at once (under 1 s).
Every answer's status is checked against what the API promises (docs/serve.md); the
server's resident memory is sampled throughout. Afterwards the lighting the server started
with is put back and the relit values and lux must be byte for byte those it gave at the
start, and the server must still answer.

Usage: load_test.py PENUMBRA_BINARY SOURCE_DIR [--seconds S] [--clients N] [--slow N]
                    [--json FILE]
Exit status 0 when every check held; the figures (requests, errors, latency percentiles,
peak memory) are printed either way.
"""
import argparse
import http.client
import json
import os
import pathlib
import random
import socket
import statistics
import subprocess
import sys
import threading
import time

LIGHTS = ["downlight", "spot"]


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binary")
    parser.add_argument("source_dir")
    parser.add_argument("--seconds", type=float, default=10)
    parser.add_argument("--clients", type=int, default=6)
    parser.add_argument("--slow", type=int, default=2)
    parser.add_argument("--json", help="also write the figures to this file")
    parser.add_argument("--no-memory-bound", action="store_true",
                        help="do not fail on memory growth (AddressSanitizer's quarantine keeps "
                             "up to 256 MB of freed memory resident: the growth is not the server's)")
    return parser.parse_args()


class Server:
    """The penumbra serve process on an ephemeral loopback port."""

    def __init__(self, binary, scene):
        self.process = subprocess.Popen(
            [binary, "serve", str(scene), "--port", "0", "--degree", "4", "--patch-size", "0.5"],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        line = self.process.stdout.readline()  # "penumbra serve: http://127.0.0.1:PORT/ (...)"
        if "http://" not in line:
            raise SystemExit(f"load_test: the server did not start: {line!r}")
        self.port = int(line.split("http://")[1].split("/")[0].rsplit(":", 1)[1])

    def status_kb(self, field):
        """A memory figure of the process from /proc (VmRSS now, VmHWM its peak), in kB."""
        with open(f"/proc/{self.process.pid}/status") as status:
            for line in status:
                if line.startswith(field + ":"):
                    return int(line.split()[1])
        return 0

    def resident_kb(self):
        return self.status_kb("VmRSS")

    def peak_kb(self):
        return self.status_kb("VmHWM")

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=30)


class Tally:
    """Latencies by kind of request, and what went wrong, shared by the client threads."""

    def __init__(self):
        self.lock = threading.Lock()
        self.latency = {}
        self.problems = []

    def record(self, kind, seconds):
        with self.lock:
            self.latency.setdefault(kind, []).append(seconds)

    def problem(self, text):
        with self.lock:
            if len(self.problems) < 50:
                self.problems.append(text)


def request(connection, method, path, body=None, headers=None):
    """Sends one request on a keep-alive connection; returns (status, body bytes)."""
    connection.request(method, path, body=body, headers=headers or {})
    response = connection.getresponse()
    return response.status, response.read()


def valid_change(rng):
    """A lamp change the API accepts, with its path."""
    light = rng.choice(LIGHTS)
    relight = "?relight=1" if rng.random() < 0.5 else ""
    choice = rng.randrange(4)
    if choice == 0:
        body = {"colour": [rng.uniform(0, 1) for _ in range(3)], "scale": rng.uniform(0, 2)}
    elif choice == 1:
        body = {"aim": [rng.uniform(0.5, 3.5), rng.uniform(0.5, 2.5), 0]}
    elif choice == 2:
        body = {"sigma": rng.random() < 0.5, "scale": rng.uniform(0.1, 1)}
    else:
        return f"/api/lights/{light}/control{relight}", {"index": rng.randrange(19),
                                                          "candela": rng.uniform(0, 500)}
    return f"/api/lights/{light}{relight}", body


def client(port, seed, deadline, tally, patches):
    """One client: a keep-alive connection making a mix of good and bad requests."""
    rng = random.Random(seed)
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    json_headers = {"Content-Type": "application/json"}
    while time.monotonic() < deadline:
        roll = rng.random()
        start = time.monotonic()
        try:
            if roll < 0.35:
                kind, (path, body) = "change lamp", valid_change(rng)
                status, _ = request(connection, "POST", path, json.dumps(body), json_headers)
                expected = {200}
            elif roll < 0.55:
                kind, path = "relight", "/api/relight"
                status, _ = request(connection, "GET", path)
                expected = {200}
            elif roll < 0.70:
                kind, path = "lux", f"/api/lux?patch={rng.randrange(patches)}"
                status, _ = request(connection, "GET", path)
                expected = {200}
            elif roll < 0.78:
                kind, path = "lights", "/api/lights"
                status, _ = request(connection, "GET", path)
                expected = {200}
            else:
                kind, path, status, expected = malformed(rng, connection, port)
                if status is None:  # a raw-socket request: its own connection
                    tally.record(kind, time.monotonic() - start)
                    continue
        except (OSError, http.client.HTTPException) as error:
            tally.problem(f"client {seed}: {type(error).__name__}: {error}")
            connection.close()
            connection = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
            continue
        tally.record(kind, time.monotonic() - start)
        if status not in expected:
            tally.problem(f"{kind} {path}: status {status}, expected {sorted(expected)}")
        if status == 413:  # the server closes the connection after refusing a body
            connection.close()
            connection = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
    connection.close()


def malformed(rng, connection, port):
    """One bad request: returns (kind, path, status or None, expected statuses)."""
    json_headers = {"Content-Type": "application/json"}
    choice = rng.randrange(8)
    if choice == 0:
        path = f"/api/lights/{rng.choice(LIGHTS)}"
        status, _ = request(connection, "POST", path, "{not json", json_headers)
        return "bad JSON", path, status, {400}
    if choice == 1:
        path = f"/api/lights/{rng.choice(LIGHTS)}"
        body = rng.choice(['{"scale": -1}', '{"colour": [1, 2]}', '{"aim": "up"}',
                           '{"controls": [1, 2, 3]}', '{"scale": 1e400}'])
        status, _ = request(connection, "POST", path, body, json_headers)
        return "bad value", path, status, {400}
    if choice == 2:
        path = rng.choice(["/api/lights/no-such-lamp", "/api/nothing", "/no-such-file.js"])
        status, _ = request(connection, "GET", path)
        return "unknown", path, status, {404}
    if choice == 3:
        path = rng.choice(["/api/lux?patch=-1", "/api/lux?patch=1e9", "/api/lux?x=nan&y=0&z=0",
                           "/api/lux"])
        status, _ = request(connection, "GET", path)
        return "bad query", path, status, {400, 404}
    if choice == 4:
        path = rng.choice(["/api/relight", "/api/scene"])
        status, _ = request(connection, "DELETE", path)
        return "wrong method", path, status, {404, 405}
    if choice == 5:
        path = "/api/lighting"
        body = '{"lights": [' + ",".join(['{"name": "spot"}'] * 80000) + "]}"  # 1.4 MB, over the 1 MiB limit
        try:
            status, _ = request(connection, "PUT", path, body, json_headers)
        except (BrokenPipeError, ConnectionResetError):
            status = 413  # refused before the body was sent
        return "oversized", path, status, {413}
    # raw sockets: garbage, and a request whose body never comes
    data = (bytes(rng.randrange(256) for _ in range(rng.randrange(1, 400))) if choice == 6
            else b"POST /api/lights/spot HTTP/1.1\r\nHost: x\r\nContent-Length: 1000\r\n\r\n{\"sc")
    with socket.create_connection(("127.0.0.1", port), timeout=30) as raw:
        raw.sendall(data)
        raw.shutdown(socket.SHUT_WR)
        while raw.recv(65536):
            pass
    return ("garbage" if choice == 6 else "cut off"), "", None, set()


def slow_client(port, seed, deadline, tally):
    """Sends GET /api/lights one byte every 50 ms, again and again; the answer must be whole."""
    data = b"GET /api/lights HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n"
    while time.monotonic() < deadline:
        start = time.monotonic()
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=60) as raw:
                for k in range(len(data)):
                    raw.sendall(data[k:k + 1])
                    time.sleep(0.05)
                answer = b""
                while chunk := raw.recv(65536):
                    answer += chunk
        except OSError as error:
            tally.problem(f"slow client {seed}: {error}")
            continue
        tally.record("slow client", time.monotonic() - start)
        head, _, body = answer.partition(b"\r\n\r\n")
        if not head.startswith(b"HTTP/1.1 200") or "lights" not in json.loads(body):
            tally.problem(f"slow client {seed}: answer {head[:40]!r}")


def wait_behind_idle_connections(port, idle_count=16):
    """The longest a new connection waits for its answer while up to idle_count keep-alive
    connections, each having made one request, stay open: the server must not give every thread to idle
    connections (cpp-httplib holds a thread per connection; with 8 threads a ninth connection
    waited for an idle one's keep-alive time, 5 s)."""
    connections = [http.client.HTTPConnection("127.0.0.1", port, timeout=60)
                   for _ in range(idle_count + 1)]
    waited = 0
    for connection in connections:  # each one's request while the earlier ones stay open
        start = time.monotonic()
        status, _ = request(connection, "GET", "/api/lights")
        waited = max(waited, time.monotonic() - start if status == 200 else float("inf"))
    for connection in connections:
        connection.close()
    return waited


def percentile(values, fraction):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def main():
    args = parse_arguments()
    scene = pathlib.Path(args.source_dir) / "fixtures" / "scenes" / "serve-room.json"
    started = time.monotonic()
    server = Server(args.binary, scene)
    print(f"load_test: server up on port {server.port} in {time.monotonic() - started:.1f} s")
    failures = []
    try:
        connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=60)
        _, lighting = request(connection, "GET", "/api/lighting")
        _, relit_before = request(connection, "GET", "/api/relight")
        patches = json.loads(request(connection, "GET", "/api/scene")[1])["patches"]
        lux_before = [request(connection, "GET", f"/api/lux?patch={k}")[1]
                      for k in range(0, patches, max(1, patches // 20))]
        resident_start = server.resident_kb()
        waited = wait_behind_idle_connections(server.port)
        if waited > 1.0:
            failures.append(f"a new connection waited {waited:.1f} s behind 16 idle ones")

        tally = Tally()
        samples = []
        deadline = time.monotonic() + args.seconds
        threads = [threading.Thread(target=client, args=(server.port, k, deadline, tally, patches))
                   for k in range(args.clients)]
        threads += [threading.Thread(target=slow_client, args=(server.port, 100 + k, deadline, tally))
                    for k in range(args.slow)]
        load_start = time.monotonic()
        for thread in threads:
            thread.start()
        while any(thread.is_alive() for thread in threads):
            samples.append((time.monotonic() - load_start, server.resident_kb()))
            time.sleep(0.2)
        load_seconds = time.monotonic() - load_start
        if server.process.poll() is not None:
            failures.append(f"the server exited with status {server.process.returncode}")

        # the starting lighting back: the same answers, byte for byte (a new connection: the
        # first has been idle past the server's keep-alive time)
        connection.close()
        connection = http.client.HTTPConnection("127.0.0.1", server.port, timeout=60)
        status, _ = request(connection, "PUT", "/api/lighting", lighting,
                            {"Content-Type": "application/json"})
        _, relit_after = request(connection, "GET", "/api/relight")
        lux_after = [request(connection, "GET", f"/api/lux?patch={k}")[1]
                     for k in range(0, patches, max(1, patches // 20))]
        if status != 200 or relit_after != relit_before:
            failures.append("the relit values differ from the start's once its lighting is back")
        if lux_after != lux_before:
            failures.append("lux differs from the start's once its lighting is back")
        connection.close()

        # bounded memory: the last third of the run holds no more than the first third
        third = [kb for t, kb in samples if t < load_seconds / 3]
        last = [kb for t, kb in samples if t > 2 * load_seconds / 3]
        growth_mb = (max(last) - max(third)) / 1024 if third and last else 0
        peak_mb = server.peak_kb() / 1024
        if growth_mb > 64 and not args.no_memory_bound:
            failures.append(f"resident memory grew by {growth_mb:.0f} MB over the run")
    finally:
        server.stop()

    every = [s for values in tally.latency.values() for s in values]
    api = [s for kind in ("change lamp", "relight", "lux", "lights")
           for s in tally.latency.get(kind, [])]
    figures = {
        "seconds": round(load_seconds, 1),
        "clients": args.clients,
        "slow_clients": args.slow,
        "requests": len(every),
        "requests_per_second": round(len(every) / load_seconds, 1),
        "unexpected": len(tally.problems),
        "p50_ms": round(1000 * percentile(every, 0.5), 2),
        "p99_ms": round(1000 * percentile(every, 0.99), 2),
        "api_p50_ms": round(1000 * percentile(api, 0.5), 2),
        "api_p99_ms": round(1000 * percentile(api, 0.99), 2),
        "by_kind": {kind: {"requests": len(values),
                           "p50_ms": round(1000 * percentile(values, 0.5), 2),
                           "p99_ms": round(1000 * percentile(values, 0.99), 2)}
                    for kind, values in sorted(tally.latency.items())},
        "wait_behind_16_idle_ms": round(1000 * waited, 2),
        "resident_mb_at_start": round(resident_start / 1024, 1),
        "peak_resident_mb": round(peak_mb, 1),
        "growth_last_third_mb": round(growth_mb, 1),
    }
    print(json.dumps(figures, indent=2))
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(figures, indent=2) + "\n")
    failures += tally.problems
    for failure in failures:
        print(f"load_test: FAILED: {failure}", file=sys.stderr)
    missing = {"change lamp", "relight", "lux", "slow client" if args.slow else "relight"}
    missing -= set(tally.latency)
    if missing:
        print(f"load_test: FAILED: no {', '.join(sorted(missing))} request completed",
              file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
