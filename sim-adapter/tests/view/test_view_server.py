# SPDX-License-Identifier: EPL-2.0
"""The loopback server: the packaged page, /config.json, the hello that `rei run --view` waits for."""

from __future__ import annotations

import json
import threading
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from rei.view import STATIC_DIR, ViewServer, ViewServerError

CONFIG = {"format": "rei-view/1", "run_id": "r"}


def get(url: str) -> tuple[int, str, bytes]:
    try:
        with urllib.request.urlopen(url, timeout=5) as response:
            return response.status, response.headers["Content-Type"], response.read()
    except urllib.error.HTTPError as error:
        return error.code, error.headers["Content-Type"], error.read()


def test_it_serves_the_built_page_and_its_assets_on_loopback() -> None:
    with ViewServer(CONFIG) as server:
        assert server.url.startswith("http://127.0.0.1:")
        status, kind, body = get(server.url)
        assert status == 200 and kind.startswith("text/html")
        # the same build holds the room editor's page (rei edit serves it); every asset belongs to one of the two
        status, kind, editor = get(server.url + "edit.html")
        assert status == 200 and kind.startswith("text/html")
        assets = [p for p in (STATIC_DIR / "assets").iterdir()]
        assert {p.suffix for p in assets} == {".js", ".css"}
        for asset in assets:
            assert f"assets/{asset.name}".encode() in body + editor
            status, kind, served = get(server.url + f"assets/{asset.name}")
            assert status == 200 and served == asset.read_bytes()
            assert "javascript" in kind or kind.startswith("text/css")


def test_config_json_is_the_given_configuration_plus_where_to_say_hello() -> None:
    with ViewServer(CONFIG) as server:
        status, kind, body = get(server.url + "config.json")
    assert status == 200 and kind == "application/json"
    assert json.loads(body) == {**CONFIG, "hello": "/hello"}


@pytest.mark.parametrize("path", ["../server.py", "%2e%2e/server.py", "assets/../../config.py", "nothing.js"])
def test_nothing_outside_the_static_folder_is_served(path: str) -> None:
    with ViewServer(CONFIG) as server:
        status, _, body = get(server.url + path)
    assert status == 404 and b"import" not in body


def test_waiting_for_a_viewer_ends_with_its_hello_or_the_timeout() -> None:
    with ViewServer(CONFIG) as server:
        started = time.monotonic()
        assert server.wait_for_viewer(0.3) is False
        assert 0.25 < time.monotonic() - started < 3
        request = urllib.request.Request(server.url + "hello", method="POST")
        threading.Timer(0.2, lambda: urllib.request.urlopen(request, timeout=5).close()).start()
        assert server.wait_for_viewer(5.0) is True
        assert server.viewers == 1
        assert server.wait_for_viewer(0.0) is True


def test_an_unbuilt_page_is_a_clear_error(tmp_path: Path) -> None:
    with pytest.raises(ViewServerError, match="npm run build"):
        ViewServer(CONFIG, static_dir=tmp_path)


def test_stop_frees_the_port() -> None:
    server = ViewServer(CONFIG).start()
    url = server.url
    server.stop()
    with pytest.raises(urllib.error.URLError):
        urllib.request.urlopen(url, timeout=2)
    server.stop()  # twice is harmless
