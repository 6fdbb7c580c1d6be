#!/usr/bin/python3
"""A contact sheet: many frames (EXR or PNG) as small pictures in a grid, in one sRGB PNG, to
look at a rendered range at a glance (the farm jobs' last step, docs/farm.md).

    contact_sheet.py FRAMES... -o SHEET.png [--columns N] [--width PIXELS]

Frames go left to right, top to bottom, in the order given (a shell glob of zero-padded names
is frame order). EXR frames are linear and are encoded to sRGB; PNGs are taken as they are.
Written to a temporary file and renamed: the sheet is whole or not there.
"""
import argparse
import math
import os
import sys

import OpenImageIO as oiio


def thumbnail(path, width):
    image = oiio.ImageBuf(path)
    if image.has_error:
        sys.exit(f"contact_sheet: cannot read {path}: {image.geterror()}")
    spec = image.spec()
    # A part of a larger image (a region) is shown in its place in the whole.
    if (spec.full_width, spec.full_height) != (spec.width, spec.height):
        image = oiio.ImageBufAlgo.crop(image, oiio.get_roi_full(spec))
    height = max(1, round(width * spec.full_height / spec.full_width))
    colour = oiio.ImageBufAlgo.channels(image, (0, 1, 2))
    small = oiio.ImageBufAlgo.resize(colour, roi=oiio.ROI(0, width, 0, height, 0, 1, 0, 3))
    if path.lower().endswith(".exr"):
        small = oiio.ImageBufAlgo.colorconvert(small, "linear", "sRGB")
    return small


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frames", nargs="+", help="images, in order")
    parser.add_argument("-o", "--output", required=True, help="the sheet: a .png")
    parser.add_argument("--columns", type=int, default=0,
                        help="pictures a row (default: as square a sheet as the count allows)")
    parser.add_argument("--width", type=int, default=160, help="each picture's width in pixels")
    args = parser.parse_args()
    if not args.output.lower().endswith(".png"):
        sys.exit("contact_sheet: the sheet must be a .png")
    if args.width < 8:
        sys.exit("contact_sheet: --width must be at least 8")
    columns = args.columns or math.ceil(math.sqrt(len(args.frames)))
    rows = math.ceil(len(args.frames) / columns)
    gap = 2
    pictures = [thumbnail(path, args.width) for path in args.frames]
    height = max(p.spec().height for p in pictures)
    sheet = oiio.ImageBuf(oiio.ImageSpec(columns * (args.width + gap) + gap,
                                         rows * (height + gap) + gap, 3, "float"))
    oiio.ImageBufAlgo.fill(sheet, (0.1, 0.1, 0.1))
    for k, picture in enumerate(pictures):
        x = gap + (k % columns) * (args.width + gap)
        y = gap + (k // columns) * (height + gap)
        oiio.ImageBufAlgo.paste(sheet, x, y, 0, 0, picture)
    directory, name = os.path.split(os.path.abspath(args.output))
    temp = os.path.join(directory, f".{name}.tmp-{os.getpid()}.png")
    try:
        if not sheet.write(temp, "uint8"):
            sys.exit(f"contact_sheet: cannot write {args.output}: {sheet.geterror()}")
        os.replace(temp, args.output)
    finally:
        if os.path.exists(temp):
            os.remove(temp)
    print(f"contact_sheet: {len(pictures)} frames -> {args.output} ({columns} x {rows})",
          file=sys.stderr)


if __name__ == "__main__":
    main()
