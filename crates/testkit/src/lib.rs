//! Inputs the tests of several crates and the fuzz loop share: pictures
//! whose headers claim huge sizes (decompression bombs), SVG bombs, and the
//! closed box mesh, and an independent replay of disassembly plans
//! ([`disassembly`]). Plain bytes and strings: no dependency, no I/O.
//! Besides, [`repo`]: where the tests find the benchmark instances of the
//! repository and how they run the independent solution checkers (this
//! module reads files and runs processes).

pub mod disassembly;
pub mod repo;

/// An SVG of 111 bytes whose width and height are 10^9: a renderer that
/// trusts them allocates 10^18 pixels.
pub const HUGE_SVG: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="1e9" height="1e9"><rect width="1e9" height="1e9"/></svg>"#;

/// A 10×10 SVG whose rectangle sits inside `depth` nested `<g>` elements
/// (50,000 overflow the stack of a recursive reader).
pub fn nested_svg(depth: usize) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">{}<rect width="5" height="5"/>{}</svg>"#,
        "<g>".repeat(depth),
        "</g>".repeat(depth)
    )
}

/// CRC-32 (ISO-HDLC, as PNG chunks use it).
pub fn crc32(data: &[u8]) -> u32 {
    let mut c = 0xFFFF_FFFFu32;
    for &b in data {
        c ^= b as u32;
        for _ in 0..8 {
            c = if c & 1 == 1 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

/// A valid PNG whose header says `w`×`h` grey pixels, followed by a few
/// bytes of compressed data: a decoder that trusts the header allocates
/// `w·h` bytes or more.
pub fn png_claiming(w: u32, h: u32) -> Vec<u8> {
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        out.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        out.extend_from_slice(&body);
        out.extend_from_slice(&crc32(&body).to_be_bytes());
    };
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&w.to_be_bytes());
    ihdr.extend_from_slice(&h.to_be_bytes());
    ihdr.extend_from_slice(&[8, 0, 0, 0, 0]);
    chunk(b"IHDR", &ihdr);
    // A zlib stream of a few zero bytes (one stored block), then the end.
    chunk(
        b"IDAT",
        &[0x78, 0x01, 0x01, 0x05, 0x00, 0xFA, 0xFF, 0, 0, 0, 0, 0],
    );
    chunk(b"IEND", &[]);
    out
}

/// A baseline JPEG header (SOF0) saying `w`×`h`, with nothing after it.
pub fn jpeg_claiming(w: u16, h: u16) -> Vec<u8> {
    let mut out = vec![0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 0x08];
    out.extend_from_slice(&h.to_be_bytes());
    out.extend_from_slice(&w.to_be_bytes());
    out.extend_from_slice(&[3, 1, 0x22, 0, 2, 0x11, 1, 3, 0x11, 1, 0xFF, 0xD9]);
    out
}

/// The 12 triangles of the closed box from `lo` to `hi`, each facing
/// outward (counter-clockwise seen from outside).
pub fn box_triangles(lo: [f64; 3], hi: [f64; 3]) -> Vec<[[f64; 3]; 3]> {
    let p = |x: usize, y: usize, z: usize| {
        [
            if x == 0 { lo[0] } else { hi[0] },
            if y == 0 { lo[1] } else { hi[1] },
            if z == 0 { lo[2] } else { hi[2] },
        ]
    };
    let quads = [
        [p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)],
        [p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)],
        [p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)],
        [p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0)],
        [p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0)],
        [p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)],
    ];
    quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect()
}

/// Triangles as an ASCII STL solid named `name`.
pub fn ascii_stl(name: &str, triangles: &[[[f64; 3]; 3]]) -> String {
    let mut out = format!("solid {name}\n");
    for t in triangles {
        out += "facet normal 0 0 0\nouter loop\n";
        for p in t {
            out += &format!("vertex {} {} {}\n", p[0], p[1], p[2]);
        }
        out += "endloop\nendfacet\n";
    }
    out + &format!("endsolid {name}\n")
}

/// Triangles as a binary STL (80-byte header, count, 50 bytes a triangle).
pub fn binary_stl(triangles: &[[[f64; 3]; 3]]) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for t in triangles {
        out.extend_from_slice(&[0u8; 12]);
        for p in t {
            for c in p {
                out.extend_from_slice(&(*c as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&[0, 0]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_of_the_standard_check_string() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn the_png_header_says_what_was_asked() {
        let png = png_claiming(20_000, 3);
        assert_eq!(&png[12..16], b"IHDR");
        assert_eq!(&png[16..20], &20_000u32.to_be_bytes());
        assert_eq!(&png[20..24], &3u32.to_be_bytes());
        assert!(png.ends_with(&[0xAE, 0x42, 0x60, 0x82]), "IEND's CRC");
    }

    #[test]
    fn the_box_is_closed_and_faces_outward() {
        let tris = box_triangles([0.0; 3], [2.0, 3.0, 4.0]);
        assert_eq!(tris.len(), 12);
        // Signed volume (divergence theorem): positive and the box's.
        let v: f64 = tris
            .iter()
            .map(|[a, b, c]| {
                (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    / 6.0
            })
            .sum();
        assert!((v - 24.0).abs() < 1e-9, "{v}");
        assert_eq!(binary_stl(&tris).len(), 84 + 12 * 50);
        assert!(ascii_stl("b", &tris).starts_with("solid b\n"));
    }
}
