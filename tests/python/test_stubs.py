"""The type stubs shipped with the package are those the built module gives, and cover every
public name."""

import ast
import subprocess
import sys

import momenta

from conftest import SOURCE_DIR


def test_stubs_are_up_to_date():
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "scripts" / "generate_python_stubs.py"),
                             "--check"], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_public_name_has_a_stub():
    for module, file in [(momenta, "__init__.pyi"), (momenta.inertia, "inertia.pyi")]:
        tree = ast.parse((SOURCE_DIR / "python" / "momenta" / file).read_text())
        stubbed = {node.name for node in tree.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
        stubbed |= {alias.asname or alias.name for node in tree.body if isinstance(node, ast.ImportFrom)
                    for alias in node.names}
        stubbed |= {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}
        missing = [name for name in module.__all__ if name not in stubbed and name != "inertia"
                   and not name.startswith("_")]
        assert not missing, f"{file} lacks {missing}"
