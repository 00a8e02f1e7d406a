#!/bin/bash
# mk/venv.sh PYTHON DIR: a virtual environment in DIR that imports mlgshimmy
# from drivers/ (edits take effect at once). A .pth file instead of
# `pip install -e .`: pip's editable install needs setuptools' bdist_wheel,
# which pyenv's and conda's interpreters often lack, and the network.
set -euo pipefail
python=$1 dir=$2
drivers=$(cd "$(dirname "$0")/../drivers" && pwd)
need="the interpreter must be Python >= 3.9 with numpy, scipy and matplotlib: Debian's /usr/bin/python3 has them (make setup installs them), or give PYTHON=<such an interpreter>"
if ! version=$("$python" -c 'import sys; print("%d.%d" % sys.version_info[:2]); assert sys.version_info >= (3, 9)' 2>/dev/null); then
    echo "venv: PYTHON=$python is not Python >= 3.9 (${version:-it does not run}); $need" >&2
    exit 1
fi
for module in numpy scipy matplotlib; do
    if ! "$python" -c "import $module" 2>/dev/null; then
        echo "venv: PYTHON=$python (Python $version) has no $module; $need" >&2
        exit 1
    fi
done
"$python" -m venv --system-site-packages "$dir"
site=$("$dir/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
printf '%s\n' "$drivers" > "$site/mlgshimmy.pth"
"$dir/bin/python" -c 'import mlgshimmy.shared.mlgmodel'
echo "venv: $dir/bin/python (Python $version) imports mlgshimmy from $drivers; activate with . $dir/bin/activate"
