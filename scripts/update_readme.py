#!/usr/bin/python3
"""Copies docs/results/NAME.md into README.md between the markers
<!-- results:NAME --> and <!-- /results:NAME -->, so that every number in the
README comes from a script. Run after the validation and benchmark scripts."""
import os
import re

import cosph_results as cr


def main():
    readme_path = os.path.join(cr.REPO, "README.md")
    readme = open(readme_path).read()

    def fill(match):
        name = match.group(1)
        path = os.path.join(cr.RESULTS, name + ".md")
        body = open(path).read().strip() if os.path.exists(path) else \
            f"_(no results yet: run the script that writes docs/results/{name}.md)_"
        return f"<!-- results:{name} -->\n{body}\n<!-- /results:{name} -->"

    updated = re.sub(r"<!-- results:([\w-]+) -->.*?<!-- /results:\1 -->", fill, readme,
                     flags=re.S)
    with open(readme_path, "w") as f:
        f.write(updated)
    print("README.md updated" if updated != readme else "README.md already up to date")


if __name__ == "__main__":
    main()
