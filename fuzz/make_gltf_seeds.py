#!/usr/bin/env python3
"""Writes the seed corpus of the glTF harness, fuzz/corpus/gltf/: small skinned, animated
documents of our own (never copies of ../shared data), valid ones and ones that the loader must
reject with GltfError (out-of-range indices, accessors past their buffer view, NaN / zero /
non-unit rotations in animation samplers, truncated GLB). Usage: make_gltf_seeds.py OUT_DIR"""
import base64, copy, json, math, os, struct, sys


def document(rotations, times=(0.0, 1.0)):
    """Two joints, one triangle skinned to both, one rotation channel on joint 1."""
    pos = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0)
    joints = struct.pack('<12H', 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0)
    weights = struct.pack('<12f', 0.5, 0.5, 0, 0, 0.25, 0.75, 0, 0, 1, 0, 0, 0)
    idx = struct.pack('<3H', 0, 1, 2) + b'\0\0'
    ibm = struct.pack('<32f', *([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] * 2))
    t = struct.pack('<%df' % len(times), *times)
    r = b''.join(struct.pack('<4f', *q) for q in rotations)
    parts = [pos, joints, weights, idx, ibm, t, r]
    views, blob = [], b''
    for p in parts:
        views.append({'buffer': 0, 'byteOffset': len(blob), 'byteLength': len(p)})
        blob += p + b'\0' * (-len(p) % 4)
    acc = [
        {'bufferView': 0, 'componentType': 5126, 'count': 3, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [1, 1, 0]},
        {'bufferView': 1, 'componentType': 5123, 'count': 3, 'type': 'VEC4'},
        {'bufferView': 2, 'componentType': 5126, 'count': 3, 'type': 'VEC4'},
        {'bufferView': 3, 'componentType': 5123, 'count': 3, 'type': 'SCALAR'},
        {'bufferView': 4, 'componentType': 5126, 'count': 2, 'type': 'MAT4'},
        {'bufferView': 5, 'componentType': 5126, 'count': len(times), 'type': 'SCALAR', 'min': [min(times)], 'max': [max(times)]},
        {'bufferView': 6, 'componentType': 5126, 'count': len(rotations), 'type': 'VEC4'},
    ]
    return {
        'asset': {'version': '2.0', 'generator': 'rotorcert fuzz seeds'},
        'scene': 0, 'scenes': [{'nodes': [0, 2]}],
        'nodes': [{'name': 'root', 'children': [1]}, {'name': 'tip', 'translation': [1, 0, 0]},
                  {'name': 'mesh', 'mesh': 0, 'skin': 0}],
        'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'JOINTS_0': 1, 'WEIGHTS_0': 2}, 'indices': 3}]}],
        'skins': [{'joints': [0, 1], 'inverseBindMatrices': 4}],
        'animations': [{'channels': [{'sampler': 0, 'target': {'node': 1, 'path': 'rotation'}}],
                        'samplers': [{'input': 5, 'output': 6, 'interpolation': 'LINEAR'}]}],
        'accessors': acc, 'bufferViews': views,
        'buffers': [{'byteLength': len(blob), 'uri': 'data:application/octet-stream;base64,' + base64.b64encode(blob).decode()}],
    }


def glb(doc):
    doc = copy.deepcopy(doc)
    uri = doc['buffers'][0].pop('uri')
    blob = base64.b64decode(uri.split(',', 1)[1])
    js = json.dumps(doc, separators=(',', ':')).encode()
    js += b' ' * (-len(js) % 4)
    blob += b'\0' * (-len(blob) % 4)
    body = struct.pack('<II', len(js), 0x4E4F534A) + js + struct.pack('<II', len(blob), 0x004E4942) + blob
    return struct.pack('<III', 0x46546C67, 2, 12 + len(body)) + body


def main(out):
    os.makedirs(out, exist_ok=True)
    h = math.sqrt(0.5)
    unit = [(0, 0, 0, 1), (0, 0, h, h)]
    seeds = {
        'valid_unit_rotations.gltf': document(unit),
        'non_unit_rotations.gltf': document([(0, 0, 0, 3), (0, 0, 1e-3, 1e-3)]),
        'zero_rotation.gltf': document([(0, 0, 0, 1), (0, 0, 0, 0)]),
        'three_keyframes.gltf': document(unit + [(0, 0, 1, 0)], (0.0, 0.5, 1.0)),
    }
    bad_index = document(unit); bad_index['meshes'][0]['primitives'][0]['indices'] = 99
    bad_count = document(unit); bad_count['accessors'][0]['count'] = 1000
    bad_joint = document(unit); bad_joint['skins'][0]['joints'] = [0, 7]
    bad_channel = document(unit); bad_channel['animations'][0]['channels'][0]['target']['node'] = 42
    cycle = document(unit); cycle['nodes'][1]['children'] = [0]
    seeds.update({'index_accessor_out_of_range.gltf': bad_index, 'accessor_count_past_view.gltf': bad_count,
                  'joint_out_of_range.gltf': bad_joint, 'channel_node_out_of_range.gltf': bad_channel,
                  'node_cycle.gltf': cycle})
    for name, doc in seeds.items():
        with open(os.path.join(out, name), 'w') as f:
            json.dump(doc, f, separators=(',', ':'))
    # NaN and Inf keyframes: raw float bits in the buffer (JSON cannot hold them).
    for name, bits in (('nan_rotation.gltf', 0x7fc00001), ('inf_rotation.gltf', 0x7f800000)):
        doc = document(unit)
        blob = bytearray(base64.b64decode(doc['buffers'][0]['uri'].split(',', 1)[1]))
        off = doc['bufferViews'][6]['byteOffset'] + 16
        blob[off:off + 4] = struct.pack('<I', bits)
        doc['buffers'][0]['uri'] = 'data:application/octet-stream;base64,' + base64.b64encode(bytes(blob)).decode()
        with open(os.path.join(out, name), 'w') as f:
            json.dump(doc, f, separators=(',', ':'))
    with open(os.path.join(out, 'valid.glb'), 'wb') as f:
        f.write(glb(document(unit)))
    with open(os.path.join(out, 'truncated.glb'), 'wb') as f:
        f.write(glb(document(unit))[:-9])


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), 'corpus', 'gltf'))
