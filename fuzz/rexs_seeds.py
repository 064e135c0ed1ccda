"""Seeds for the REXS fuzzer (fuzz/rexs_fuzzer.cpp): each input's first byte picks the form
(0 XML, 1 JSON, 2 zip). Seeds: a small XML model written here, and the REXS models of
../shared/rexs when present (each in its own form, and zipped).

Usage: rexs_seeds.py CORPUS_DIR [REXS_DIR]"""

import io
import pathlib
import sys
import zipfile

SMALL = b"""<?xml version="1.0"?>
<model applicationId="seed" applicationVersion="1" version="1.6"><relations>
<relation id="1" type="assembly"><ref id="1" role="assembly"/><ref id="3" role="part"/></relation>
<relation id="2" type="assembly"><ref id="2" role="assembly"/><ref id="4" role="part"/></relation>
<relation id="3" type="stage"><ref id="5" role="stage"/><ref id="3" role="gear_1"/><ref id="4" role="gear_2"/></relation>
</relations><components>
<component id="1" name="Input" type="shaft"><attribute id="defines_speed" unit="none">true</attribute>
<attribute id="rotational_speed" unit="1 / min">1500</attribute></component>
<component id="2" name="Output" type="shaft"/>
<component id="3" name="Pinion" type="cylindrical_gear"><attribute id="number_of_teeth" unit="none">20</attribute>
<attribute id="normal_module" unit="mm">3</attribute><attribute id="face_width" unit="mm">30</attribute></component>
<component id="4" name="Wheel" type="cylindrical_gear"><attribute id="number_of_teeth" unit="none">41</attribute>
<attribute id="normal_module" unit="mm">3</attribute><attribute id="face_width" unit="mm">28</attribute></component>
<component id="5" name="Stage" type="cylindrical_stage"><attribute id="center_distance" unit="mm">92</attribute></component>
</components></model>
"""


def zipped(name, data):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr(name, data)
    return buffer.getvalue()


def main(corpus, rexs_dir=None):
    corpus = pathlib.Path(corpus)
    corpus.mkdir(parents=True, exist_ok=True)
    (corpus / "small_xml").write_bytes(b"\x00" + SMALL)
    (corpus / "small_zip").write_bytes(b"\x02" + zipped("model.rexs", SMALL))
    if rexs_dir and pathlib.Path(rexs_dir).is_dir():
        for path in sorted(pathlib.Path(rexs_dir).iterdir()):
            data = path.read_bytes()
            if path.suffix == ".rexs":
                (corpus / path.stem).write_bytes(b"\x00" + data)
            elif path.suffix == ".rexsj":
                (corpus / (path.stem + "_json")).write_bytes(b"\x01" + data)
            else:
                continue
            (corpus / (path.stem + path.suffix[1:] + "_zip")).write_bytes(
                b"\x02" + zipped("model" + path.suffix, data))


if __name__ == "__main__":
    main(*sys.argv[1:])
