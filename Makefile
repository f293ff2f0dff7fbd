# Quickstart: `make demo` (set-up + main job) and `make test` (set-up + tests).
PY ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.lucifer-installed
EXTRAS ?= dev,llamacpp,openai,ner

.PHONY: setup demo test lint bench clean-cache

$(BIN)/python:
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip

# llama.cpp is built for a portable x86-64 (AVX2) target: a -march=native build enables AMX
# kernels that crash inside VMs that do not grant AMX state.
LLAMA_CMAKE_ARGS ?= -DGGML_NATIVE=OFF -DGGML_AVX=ON -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON -DGGML_AVX512=OFF -DGGML_AMX_INT8=OFF -DGGML_AMX_TILE=OFF

# torch first, pinned to the CPU build on this disk: anything that pulls torch later finds it.
$(STAMP): pyproject.toml $(BIN)/python
	$(BIN)/python -m pip install -q torch==2.13.0
	CMAKE_ARGS="$(LLAMA_CMAKE_ARGS)" CMAKE_BUILD_PARALLEL_LEVEL=2 $(BIN)/python -m pip install -q -e '.[$(EXTRAS)]'
	touch $(STAMP)

setup: $(STAMP)

demo: setup
	HF_HUB_OFFLINE=1 $(BIN)/lucifer demo

test: setup
	HF_HUB_OFFLINE=1 $(BIN)/python -m pytest -q -rs

lint: setup
	$(BIN)/ruff check lucifer tests

bench: setup
	HF_HUB_OFFLINE=1 $(BIN)/python benchmarks/run_all.py

clean-cache:
	rm -rf .lucifer
