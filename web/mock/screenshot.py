"""Screenshots of the editor page with headless Chromium (Playwright).

python web/mock/screenshot.py URL OUT.png [--expand NAME] [--select NAME] [--clear-storage]
"""

import argparse

from playwright.sync_api import sync_playwright

ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("url")
    parser.add_argument("out")
    parser.add_argument("--expand", action="append", default=[])
    parser.add_argument("--collapse", action="append", default=[])
    parser.add_argument("--select")
    args = parser.parse_args()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=ARGS)
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        messages = []
        page.on("console", lambda m: messages.append(f"{m.type}: {m.text}"))
        page.on("pageerror", lambda e: messages.append(f"pageerror: {e}"))
        page.goto(args.url)
        page.get_by_role("application", name="Diagram").locator(
            ".react-flow__node"
        ).first.wait_for()
        page.wait_for_timeout(600)
        for name in args.collapse:
            page.locator(f'.react-flow__node[aria-label="{name}"]').get_by_role(
                "button", name="Collapse"
            ).click()
            page.wait_for_timeout(600)
        for name in args.expand:
            page.locator(f'.react-flow__node[aria-label="{name}"]').get_by_role(
                "button", name="Expand"
            ).click()
            page.wait_for_timeout(600)
        if args.expand or args.collapse:
            page.get_by_role("button", name="Fit view").click()
            page.wait_for_timeout(500)
        if args.select:
            page.locator(f'.react-flow__node[aria-label="{args.select}"]').click()
            page.wait_for_timeout(400)
        page.screenshot(path=args.out)
        browser.close()
    for message in messages:
        print(message)


if __name__ == "__main__":
    main()
