#!/usr/bin/env python3
"""Rewrites a PP-OCR ONNX graph into one that Debian 12's OpenCV 4.6 dnn importer runs.

Measured on the PP-OCRv4 det/rec graphs of the rapidocr-onnxruntime wheel (docs/results/real-photos.md):
OpenCV 4.6 refuses them as shipped. Each rewrite below is exact (same arithmetic, same weights):
  1. Clip with min/max as inputs (opset >= 11)   -> Clip with min/max attributes (the only form 4.6 parses);
  2. Gemm with transB=0 and constant weights     -> transB=1 with the weights transposed (4.6 assumes [N, K]);
  3. Mul/Add/Sub/Div of a [B, T, C] tensor by a constant [C] vector (the unrolled LayerNorm of the
     recogniser's transformer blocks) -> the constant broadcast to [1, T, C] (4.6 maps a 1-D constant to
     a per-channel Scale on axis 1 and fails).
Shapes must be static before (3): run onnxsim with a fixed input shape first (fetch_ocr_models.sh does).
The recogniser's character list (metadata key 'character') is written beside the output as <out>.dict.txt.

Usage: patch_for_opencv.py IN.onnx OUT.onnx
"""
import sys

import numpy as np
import onnx
from onnx import helper, numpy_helper, shape_inference


def constant_tensors(graph):
    """name -> TensorProto holding its value, for initializers and Constant nodes."""
    out = {t.name: t for t in graph.initializer}
    for node in graph.node:
        if node.op_type == "Constant":
            for attr in node.attribute:
                if attr.name == "value":
                    out[node.output[0]] = attr.t
    return out


def fix_clip(graph, consts):
    count = 0
    for node in graph.node:
        if node.op_type != "Clip" or len(node.input) == 1:
            continue
        bounds = list(node.input[1:])
        for name in bounds:
            if name and name not in consts:
                raise SystemExit(f"patch_for_opencv: Clip {node.name} has a non-constant bound {name}")
        del node.input[1:]
        for attr_name, name in zip(("min", "max"), bounds):
            if name:
                node.attribute.append(helper.make_attribute(attr_name, float(numpy_helper.to_array(consts[name]))))
        count += 1
    return count


def fix_gemm(graph, consts):
    count = 0
    for node in graph.node:
        if node.op_type != "Gemm" or node.input[1] not in consts:
            continue
        attrs = {a.name: a for a in node.attribute}
        if "transB" in attrs and attrs["transB"].i == 1:
            continue
        tensor = consts[node.input[1]]
        tensor.CopyFrom(numpy_helper.from_array(numpy_helper.to_array(tensor).T.copy(), tensor.name))
        if "transB" in attrs:
            attrs["transB"].i = 1
        else:
            node.attribute.append(helper.make_attribute("transB", 1))
        count += 1
    return count


def fix_broadcast(model, consts):
    inferred = shape_inference.infer_shapes(model)
    shapes = {}
    for value in list(inferred.graph.value_info) + list(inferred.graph.input):
        dims = [d.dim_value for d in value.type.tensor_type.shape.dim]
        if dims and all(d > 0 for d in dims):
            shapes[value.name] = dims
    count = 0
    for node in model.graph.node:
        if node.op_type not in ("Mul", "Add", "Sub", "Div") or len(node.input) != 2:
            continue
        data, const = node.input
        if const not in consts or data not in shapes:
            continue
        shape = shapes[data]
        value = numpy_helper.to_array(consts[const])
        if len(shape) == 3 and value.ndim == 1 and value.shape[0] == shape[-1] and value.shape[0] > 1:
            full = np.broadcast_to(value.reshape(1, 1, -1), [1] + shape[1:]).astype(value.dtype).copy()
            consts[const].CopyFrom(numpy_helper.from_array(full, consts[const].name))
            count += 1
    return count


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    model = onnx.load(sys.argv[1])
    consts = constant_tensors(model.graph)
    counts = (fix_clip(model.graph, consts), fix_gemm(model.graph, consts), fix_broadcast(model, consts))
    meta = {p.key: p.value for p in model.metadata_props}
    if "character" in meta:
        with open(sys.argv[2] + ".dict.txt", "w", encoding="utf-8") as f:
            f.write(meta["character"])
    onnx.save(model, sys.argv[2])
    print(f"patch_for_opencv: {sys.argv[2]}: {counts[0]} Clip, {counts[1]} Gemm, {counts[2]} broadcast rewrites")


if __name__ == "__main__":
    main()
