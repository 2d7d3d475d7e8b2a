//! A small PNG encoder: CRC-32, Adler-32, zlib/DEFLATE (LZ77 with Huffman coding) and
//! the PNG chunk layout, written from the specifications.
//!
//! * PNG (ISO/IEC 15948, W3C PNG 2nd ed.): signature, `IHDR` (8-bit grey, RGB or
//!   RGBA, no interlace), one `IDAT` with the zlib stream of the filtered scanlines,
//!   `IEND`; every chunk carries the CRC-32 of its type and data. Each scanline gets the
//!   filter (None, Sub, Up, Average, Paeth) with the smallest sum of absolute values of
//!   its bytes taken as signed (the heuristic of §12.8 of the specification).
//! * zlib (RFC 1950): header `78 9C`, DEFLATE data, Adler-32 of the raw data
//!   (`a = 1 + Σ bytes`, `b = Σ a`, mod 65521; big-endian).
//! * DEFLATE (RFC 1951): LZ77 over a 32 KiB window (hash chains of 3-byte prefixes,
//!   lengths 3–258, greedy with one step of lazy matching), in blocks of at most 2¹⁶
//!   symbols; each block is written in the smallest of the three forms — stored,
//!   fixed Huffman codes, or dynamic Huffman codes (length-limited to 15 bits, code
//!   lengths to 7 bits, by the package-merge algorithm of Larmore & Hirschberg, and the
//!   code-length run-length codes 16, 17, 18).
//! * CRC-32 (ISO 3309 / ITU-T V.42, polynomial `0xEDB88320` reflected), table driven.

use crate::IoError;

// ---------------------------------------------------------------------------------
// Checksums
// ---------------------------------------------------------------------------------

const fn crc_table() -> [u32; 256] {
    let mut t = [0u32; 256];
    let mut n = 0;
    while n < 256 {
        let mut c = n as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 {
                0xEDB8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
            k += 1;
        }
        t[n] = c;
        n += 1;
    }
    t
}

static CRC_TABLE: [u32; 256] = crc_table();

/// CRC-32 (ISO 3309) of `data`, continuing from `crc` (start with 0).
pub fn crc32_update(crc: u32, data: &[u8]) -> u32 {
    let mut c = !crc;
    for &b in data {
        c = CRC_TABLE[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8);
    }
    !c
}

/// CRC-32 of `data`.
pub fn crc32(data: &[u8]) -> u32 {
    crc32_update(0, data)
}

/// Adler-32 (RFC 1950) of `data`.
pub fn adler32(data: &[u8]) -> u32 {
    const MOD: u32 = 65_521;
    let (mut a, mut b) = (1u32, 0u32);
    // 5552 bytes keep the sums below 2³²
    for chunk in data.chunks(5552) {
        for &x in chunk {
            a += u32::from(x);
            b += a;
        }
        a %= MOD;
        b %= MOD;
    }
    (b << 16) | a
}

// ---------------------------------------------------------------------------------
// Bit output
// ---------------------------------------------------------------------------------

struct Bits {
    out: Vec<u8>,
    acc: u64,
    n: u32,
}

impl Bits {
    fn new() -> Self {
        Bits {
            out: Vec::new(),
            acc: 0,
            n: 0,
        }
    }

    /// Appends the low `len` bits of `v`, least significant first.
    fn put(&mut self, v: u32, len: u32) {
        self.acc |= u64::from(v) << self.n;
        self.n += len;
        while self.n >= 8 {
            self.out.push(self.acc as u8);
            self.acc >>= 8;
            self.n -= 8;
        }
    }

    /// A Huffman code (stored most significant bit first, so reversed here).
    fn code(&mut self, code: u32, len: u32) {
        let rev = code.reverse_bits() >> (32 - len.max(1));
        self.put(if len == 0 { 0 } else { rev }, len);
    }

    fn align(&mut self) {
        if self.n > 0 {
            self.out.push(self.acc as u8);
            self.acc = 0;
            self.n = 0;
        }
    }

    fn bit_len(&self) -> u64 {
        self.out.len() as u64 * 8 + u64::from(self.n)
    }
}

// ---------------------------------------------------------------------------------
// LZ77
// ---------------------------------------------------------------------------------

/// A literal byte or a back-reference `(length, distance)`.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Sym {
    Lit(u8),
    Match(u16, u16),
}

const WINDOW: usize = 1 << 15;
const HASH_BITS: u32 = 15;
const MAX_CHAIN: usize = 96;
const MIN_MATCH: usize = 3;
const MAX_MATCH: usize = 258;

fn hash3(d: &[u8], i: usize) -> usize {
    let v = u32::from(d[i]) << 16 | u32::from(d[i + 1]) << 8 | u32::from(d[i + 2]);
    (v.wrapping_mul(0x9E37_79B1) >> (32 - HASH_BITS)) as usize
}

struct Matcher<'a> {
    d: &'a [u8],
    head: Vec<usize>,
    prev: Vec<usize>,
}

const NONE: usize = usize::MAX;

impl Matcher<'_> {
    fn insert(&mut self, i: usize) {
        if i + MIN_MATCH <= self.d.len() {
            let h = hash3(self.d, i);
            self.prev[i % WINDOW] = self.head[h];
            self.head[h] = i;
        }
    }

    /// The longest match at `i` (length, distance), length 0 if none.
    fn longest(&self, i: usize) -> (usize, usize) {
        let d = self.d;
        if i + MIN_MATCH > d.len() {
            return (0, 0);
        }
        let max = (d.len() - i).min(MAX_MATCH);
        let mut best = (0, 0);
        let mut cand = self.head[hash3(d, i)];
        let mut chain = 0;
        while cand != NONE && chain < MAX_CHAIN {
            if cand >= i || i - cand > WINDOW - 1 {
                break;
            }
            if d[cand + best.0.min(max - 1)] == d[i + best.0.min(max - 1)] {
                let mut l = 0;
                while l < max && d[cand + l] == d[i + l] {
                    l += 1;
                }
                if l > best.0 {
                    best = (l, i - cand);
                    if l == max {
                        break;
                    }
                }
            }
            let next = self.prev[cand % WINDOW];
            if next != NONE && next >= cand {
                break;
            }
            cand = next;
            chain += 1;
        }
        if best.0 >= MIN_MATCH {
            best
        } else {
            (0, 0)
        }
    }
}

/// LZ77 symbols of `d` (greedy with one step of lazy evaluation).
fn lz77(d: &[u8]) -> Vec<Sym> {
    let mut m = Matcher {
        d,
        head: vec![NONE; 1 << HASH_BITS],
        prev: vec![NONE; WINDOW],
    };
    let mut out = Vec::with_capacity(d.len() / 2);
    let mut i = 0;
    while i < d.len() {
        let (l, dist) = m.longest(i);
        if l >= MIN_MATCH {
            m.insert(i);
            // lazy: a longer match at i + 1 wins over this one
            let (l2, _) = m.longest(i + 1);
            if l2 > l {
                out.push(Sym::Lit(d[i]));
                i += 1;
                continue;
            }
            out.push(Sym::Match(l as u16, dist as u16));
            for k in i + 1..i + l {
                m.insert(k);
            }
            i += l;
        } else {
            m.insert(i);
            out.push(Sym::Lit(d[i]));
            i += 1;
        }
    }
    out
}

// ---------------------------------------------------------------------------------
// DEFLATE codes
// ---------------------------------------------------------------------------------

const LEN_BASE: [u16; 29] = [
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
    163, 195, 227, 258,
];
const LEN_EXTRA: [u8; 29] = [
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];
const DIST_BASE: [u16; 30] = [
    1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
    2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
];
const DIST_EXTRA: [u8; 30] = [
    0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13,
    13,
];
/// Order of the code-length code lengths in a dynamic block header.
const CL_ORDER: [usize; 19] = [
    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15,
];

fn len_code(l: u16) -> usize {
    LEN_BASE.iter().rposition(|&b| b <= l).unwrap_or(0)
}

fn dist_code(d: u16) -> usize {
    DIST_BASE.iter().rposition(|&b| b <= d).unwrap_or(0)
}

/// Canonical Huffman codes from code lengths (RFC 1951 §3.2.2).
fn canonical(lengths: &[u8]) -> Vec<u32> {
    let mut bl_count = [0u32; 16];
    for &l in lengths {
        bl_count[l as usize] += 1;
    }
    bl_count[0] = 0;
    let mut next = [0u32; 16];
    let mut code = 0;
    for bits in 1..16 {
        code = (code + bl_count[bits - 1]) << 1;
        next[bits] = code;
    }
    lengths
        .iter()
        .map(|&l| {
            if l == 0 {
                0
            } else {
                let c = next[l as usize];
                next[l as usize] += 1;
                c
            }
        })
        .collect()
}

/// Length-limited Huffman code lengths by package-merge. Symbols with frequency 0
/// get length 0; at least two symbols get a code (frequencies are bumped if needed).
fn huffman_lengths(freq: &[u32], limit: u8) -> Vec<u8> {
    let mut f: Vec<u64> = freq.iter().map(|&x| u64::from(x)).collect();
    let mut used = f.iter().filter(|&&x| x > 0).count();
    for x in f.iter_mut() {
        if used >= 2 {
            break;
        }
        if *x == 0 {
            *x = 1;
            used += 1;
        }
    }
    let mut leaves: Vec<(u64, usize)> = f
        .iter()
        .enumerate()
        .filter(|(_, &w)| w > 0)
        .map(|(s, &w)| (w, s))
        .collect();
    leaves.sort_unstable();
    let n = leaves.len();
    // an item is (weight, symbols it contains)
    let leaf_items: Vec<(u64, Vec<usize>)> = leaves.iter().map(|&(w, s)| (w, vec![s])).collect();
    let mut list = leaf_items.clone();
    for _ in 1..limit {
        let packages: Vec<(u64, Vec<usize>)> = list
            .chunks_exact(2)
            .map(|p| {
                let mut syms = p[0].1.clone();
                syms.extend_from_slice(&p[1].1);
                (p[0].0 + p[1].0, syms)
            })
            .collect();
        // merge leaves and packages by weight
        let mut merged = Vec::with_capacity(leaf_items.len() + packages.len());
        let (mut a, mut b) = (0, 0);
        while a < leaf_items.len() || b < packages.len() {
            let take_leaf =
                b >= packages.len() || (a < leaf_items.len() && leaf_items[a].0 <= packages[b].0);
            if take_leaf {
                merged.push(leaf_items[a].clone());
                a += 1;
            } else {
                merged.push(packages[b].clone());
                b += 1;
            }
        }
        list = merged;
    }
    let mut lengths = vec![0u8; freq.len()];
    for item in list.iter().take(2 * n - 2) {
        for &s in &item.1 {
            lengths[s] += 1;
        }
    }
    lengths
}

/// The run-length encoded code lengths (symbols 0–18 with extra bits).
fn rle_lengths(lengths: &[u8]) -> Vec<(u8, u8, u8)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < lengths.len() {
        let l = lengths[i];
        let mut run = 1;
        while i + run < lengths.len() && lengths[i + run] == l {
            run += 1;
        }
        let mut left = run;
        if l == 0 {
            while left >= 11 {
                let r = left.min(138);
                out.push((18, (r - 11) as u8, 7));
                left -= r;
            }
            if left >= 3 {
                out.push((17, (left - 3) as u8, 3));
                left = 0;
            }
        } else {
            out.push((l, 0, 0));
            left -= 1;
            while left >= 3 {
                let r = left.min(6);
                out.push((16, (r - 3) as u8, 2));
                left -= r;
            }
        }
        for _ in 0..left {
            out.push((l, 0, 0));
        }
        i += run;
    }
    out
}

fn fixed_lengths() -> (Vec<u8>, Vec<u8>) {
    let mut lit = vec![8u8; 288];
    lit[144..256].fill(9);
    lit[256..280].fill(7);
    (lit, vec![5u8; 30])
}

/// Writes the symbols of a block with the given code lengths.
fn write_symbols(bits: &mut Bits, syms: &[Sym], lit_len: &[u8], dist_len: &[u8]) {
    let lc = canonical(lit_len);
    let dc = canonical(dist_len);
    for s in syms {
        match *s {
            Sym::Lit(b) => bits.code(lc[b as usize], u32::from(lit_len[b as usize])),
            Sym::Match(l, d) => {
                let c = len_code(l);
                bits.code(lc[257 + c], u32::from(lit_len[257 + c]));
                bits.put(u32::from(l - LEN_BASE[c]), u32::from(LEN_EXTRA[c]));
                let e = dist_code(d);
                bits.code(dc[e], u32::from(dist_len[e]));
                bits.put(u32::from(d - DIST_BASE[e]), u32::from(DIST_EXTRA[e]));
            }
        }
    }
    bits.code(lc[256], u32::from(lit_len[256]));
}

/// Bits of the symbols under the given lengths (without the block header).
fn cost(syms: &[Sym], lit_len: &[u8], dist_len: &[u8]) -> u64 {
    let mut c = u64::from(lit_len[256]);
    for s in syms {
        c += match *s {
            Sym::Lit(b) => u64::from(lit_len[b as usize]),
            Sym::Match(l, d) => {
                let lc = len_code(l);
                let dc = dist_code(d);
                u64::from(lit_len[257 + lc])
                    + u64::from(LEN_EXTRA[lc])
                    + u64::from(dist_len[dc])
                    + u64::from(DIST_EXTRA[dc])
            }
        };
    }
    c
}

/// The dynamic header: (HLIT, HDIST, HCLEN, cl lengths, rle) and its size in bits.
struct DynHeader {
    lit_len: Vec<u8>,
    dist_len: Vec<u8>,
    cl_len: Vec<u8>,
    rle: Vec<(u8, u8, u8)>,
    hlit: usize,
    hdist: usize,
    hclen: usize,
}

impl DynHeader {
    fn new(syms: &[Sym]) -> Self {
        let mut lf = vec![0u32; 286];
        let mut df = vec![0u32; 30];
        lf[256] = 1;
        for s in syms {
            match *s {
                Sym::Lit(b) => lf[b as usize] += 1,
                Sym::Match(l, d) => {
                    lf[257 + len_code(l)] += 1;
                    df[dist_code(d)] += 1;
                }
            }
        }
        let lit_len = huffman_lengths(&lf, 15);
        let dist_len = huffman_lengths(&df, 15);
        let hlit = lit_len
            .iter()
            .rposition(|&l| l > 0)
            .map_or(257, |p| (p + 1).max(257));
        let hdist = dist_len.iter().rposition(|&l| l > 0).map_or(1, |p| p + 1);
        let mut all = lit_len[..hlit].to_vec();
        all.extend_from_slice(&dist_len[..hdist]);
        let rle = rle_lengths(&all);
        let mut cf = vec![0u32; 19];
        for &(s, _, _) in &rle {
            cf[s as usize] += 1;
        }
        let cl_len = huffman_lengths(&cf, 7);
        let hclen = CL_ORDER
            .iter()
            .rposition(|&s| cl_len[s] > 0)
            .map_or(4, |p| (p + 1).max(4));
        DynHeader {
            lit_len,
            dist_len,
            cl_len,
            rle,
            hlit,
            hdist,
            hclen,
        }
    }

    fn header_bits(&self) -> u64 {
        let mut c = 5 + 5 + 4 + 3 * self.hclen as u64;
        for &(s, _, eb) in &self.rle {
            c += u64::from(self.cl_len[s as usize]) + u64::from(eb);
        }
        c
    }

    fn write(&self, bits: &mut Bits) {
        bits.put((self.hlit - 257) as u32, 5);
        bits.put((self.hdist - 1) as u32, 5);
        bits.put((self.hclen - 4) as u32, 4);
        for &s in CL_ORDER.iter().take(self.hclen) {
            bits.put(u32::from(self.cl_len[s]), 3);
        }
        let cc = canonical(&self.cl_len);
        for &(s, extra, eb) in &self.rle {
            bits.code(cc[s as usize], u32::from(self.cl_len[s as usize]));
            bits.put(u32::from(extra), u32::from(eb));
        }
    }
}

/// Raw DEFLATE data of `data` (RFC 1951; module docs).
pub fn deflate(data: &[u8]) -> Vec<u8> {
    const BLOCK_SYMS: usize = 1 << 16;
    let syms = lz77(data);
    let mut bits = Bits::new();
    let (fl, fd) = fixed_lengths();
    let mut pos = 0usize; // bytes of `data` consumed
    let mut start = 0usize;
    if syms.is_empty() {
        // one empty fixed block
        bits.put(1, 1);
        bits.put(1, 2);
        write_symbols(&mut bits, &[], &fl, &fd);
        bits.align();
        return bits.out;
    }
    while start < syms.len() {
        let end = (start + BLOCK_SYMS).min(syms.len());
        let block = &syms[start..end];
        let raw_len: usize = block
            .iter()
            .map(|s| match s {
                Sym::Lit(_) => 1,
                Sym::Match(l, _) => *l as usize,
            })
            .sum();
        let last = u32::from(end == syms.len());
        let dynh = DynHeader::new(block);
        let dyn_bits = dynh.header_bits() + cost(block, &dynh.lit_len, &dynh.dist_len);
        let fixed_bits = cost(block, &fl, &fd);
        // stored: alignment, 4 bytes LEN/NLEN per 65535 bytes
        let stored_bits = 7 + (raw_len as u64).div_ceil(65_535).max(1) * 32 + raw_len as u64 * 8;
        if stored_bits < dyn_bits.min(fixed_bits) {
            let chunks: Vec<&[u8]> = data[pos..pos + raw_len].chunks(65_535).collect();
            let count = chunks.len();
            for (k, c) in chunks.into_iter().enumerate() {
                let fin = if k + 1 == count { last } else { 0 };
                bits.put(fin, 1);
                bits.put(0, 2);
                bits.align();
                let len = c.len() as u16;
                bits.out.extend_from_slice(&len.to_le_bytes());
                bits.out.extend_from_slice(&(!len).to_le_bytes());
                bits.out.extend_from_slice(c);
            }
        } else if fixed_bits <= dyn_bits {
            bits.put(last, 1);
            bits.put(1, 2);
            write_symbols(&mut bits, block, &fl, &fd);
        } else {
            bits.put(last, 1);
            bits.put(2, 2);
            dynh.write(&mut bits);
            write_symbols(&mut bits, block, &dynh.lit_len, &dynh.dist_len);
        }
        debug_assert!(bits.bit_len() > 0);
        pos += raw_len;
        start = end;
    }
    bits.align();
    bits.out
}

/// A zlib stream (RFC 1950) of `data`.
pub fn zlib_compress(data: &[u8]) -> Vec<u8> {
    let mut out = vec![0x78, 0x9C];
    out.extend(deflate(data));
    out.extend_from_slice(&adler32(data).to_be_bytes());
    out
}

// ---------------------------------------------------------------------------------
// PNG
// ---------------------------------------------------------------------------------

/// The pixel format of the raw image data (8 bits per sample).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColorType {
    /// One grey byte per pixel.
    Gray,
    /// Red, green, blue.
    Rgb,
    /// Red, green, blue, alpha.
    Rgba,
}

impl ColorType {
    fn channels(self) -> usize {
        match self {
            ColorType::Gray => 1,
            ColorType::Rgb => 3,
            ColorType::Rgba => 4,
        }
    }
    fn code(self) -> u8 {
        match self {
            ColorType::Gray => 0,
            ColorType::Rgb => 2,
            ColorType::Rgba => 6,
        }
    }
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32_update(crc32(kind), data);
    out.extend_from_slice(&crc.to_be_bytes());
}

fn paeth(a: u8, b: u8, c: u8) -> u8 {
    let p = i16::from(a) + i16::from(b) - i16::from(c);
    let (pa, pb, pc) = (
        (p - i16::from(a)).abs(),
        (p - i16::from(b)).abs(),
        (p - i16::from(c)).abs(),
    );
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

/// The filtered scanlines: each row prefixed by its filter type (module docs).
fn filter_rows(data: &[u8], width: usize, height: usize, bpp: usize) -> Vec<u8> {
    let stride = width * bpp;
    let mut out = Vec::with_capacity((stride + 1) * height);
    let zero = vec![0u8; stride];
    let mut cand = vec![0u8; stride];
    let mut best = vec![0u8; stride];
    for y in 0..height {
        let row = &data[y * stride..(y + 1) * stride];
        let up = if y == 0 {
            &zero[..]
        } else {
            &data[(y - 1) * stride..y * stride]
        };
        let mut best_f = 0u8;
        let mut best_score = u64::MAX;
        for f in 0..5u8 {
            for i in 0..stride {
                let a = if i >= bpp { row[i - bpp] } else { 0 };
                let b = up[i];
                let c = if i >= bpp { up[i - bpp] } else { 0 };
                let pred = match f {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => ((u16::from(a) + u16::from(b)) / 2) as u8,
                    _ => paeth(a, b, c),
                };
                cand[i] = row[i].wrapping_sub(pred);
            }
            let score: u64 = cand
                .iter()
                .map(|&v| u64::from((v as i8).unsigned_abs()))
                .sum();
            if score < best_score {
                best_score = score;
                best_f = f;
                best.copy_from_slice(&cand);
            }
        }
        out.push(best_f);
        out.extend_from_slice(&best);
    }
    out
}

/// A PNG file of 8-bit raw pixels, rows top to bottom (module docs).
///
/// # Errors
/// [`IoError::Invalid`] for a zero or too large size, or `data.len()` different from
/// `width · height · channels`.
pub fn encode_png(
    width: u32,
    height: u32,
    color: ColorType,
    data: &[u8],
) -> Result<Vec<u8>, IoError> {
    if width == 0 || height == 0 || width > (1 << 24) || height > (1 << 24) {
        return Err(IoError::Invalid(format!(
            "a PNG needs 1 to 2²⁴ pixels per side, got {width} × {height}"
        )));
    }
    let (w, h) = (width as usize, height as usize);
    let bpp = color.channels();
    let want = w
        .checked_mul(h)
        .and_then(|n| n.checked_mul(bpp))
        .ok_or_else(|| IoError::Invalid("the image is too large".into()))?;
    if data.len() != want {
        return Err(IoError::Invalid(format!(
            "{} bytes of pixel data for {width} × {height} pixels with {bpp} channels (need {want})",
            data.len()
        )));
    }
    let mut out = vec![0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A];
    let mut ihdr = Vec::with_capacity(13);
    ihdr.extend_from_slice(&width.to_be_bytes());
    ihdr.extend_from_slice(&height.to_be_bytes());
    ihdr.extend_from_slice(&[8, color.code(), 0, 0, 0]);
    chunk(&mut out, b"IHDR", &ihdr);
    let raw = filter_rows(data, w, h, bpp);
    chunk(&mut out, b"IDAT", &zlib_compress(&raw));
    chunk(&mut out, b"IEND", &[]);
    Ok(out)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A test-only inflater (stored, fixed and dynamic blocks), to check round trips.
    pub(crate) fn inflate(src: &[u8]) -> Option<Vec<u8>> {
        struct In<'a> {
            s: &'a [u8],
            pos: usize,
            bit: u32,
        }
        impl In<'_> {
            fn get(&mut self, n: u32) -> Option<u32> {
                let mut v = 0;
                for k in 0..n {
                    let byte = *self.s.get(self.pos)?;
                    v |= u32::from((byte >> self.bit) & 1) << k;
                    self.bit += 1;
                    if self.bit == 8 {
                        self.bit = 0;
                        self.pos += 1;
                    }
                }
                Some(v)
            }
            fn decode(&mut self, lens: &[u8]) -> Option<usize> {
                let codes = canonical(lens);
                let mut code = 0u32;
                for len in 1..=15u8 {
                    code = (code << 1) | self.get(1)?;
                    if let Some(s) = (0..lens.len()).find(|&s| lens[s] == len && codes[s] == code) {
                        return Some(s);
                    }
                }
                None
            }
        }
        let mut r = In {
            s: src,
            pos: 0,
            bit: 0,
        };
        let mut out: Vec<u8> = Vec::new();
        loop {
            let last = r.get(1)?;
            let kind = r.get(2)?;
            match kind {
                0 => {
                    if r.bit != 0 {
                        r.bit = 0;
                        r.pos += 1;
                    }
                    let len = u16::from_le_bytes([*r.s.get(r.pos)?, *r.s.get(r.pos + 1)?]) as usize;
                    r.pos += 4;
                    out.extend_from_slice(r.s.get(r.pos..r.pos + len)?);
                    r.pos += len;
                }
                1 | 2 => {
                    let (lit, dist) = if kind == 1 {
                        fixed_lengths()
                    } else {
                        let hlit = r.get(5)? as usize + 257;
                        let hdist = r.get(5)? as usize + 1;
                        let hclen = r.get(4)? as usize + 4;
                        let mut cl = vec![0u8; 19];
                        for &s in CL_ORDER.iter().take(hclen) {
                            cl[s] = r.get(3)? as u8;
                        }
                        let mut all = Vec::new();
                        while all.len() < hlit + hdist {
                            match r.decode(&cl)? {
                                s @ 0..=15 => all.push(s as u8),
                                16 => {
                                    let p = *all.last()?;
                                    for _ in 0..3 + r.get(2)? {
                                        all.push(p);
                                    }
                                }
                                17 => all.extend(std::iter::repeat_n(0, 3 + r.get(3)? as usize)),
                                _ => all.extend(std::iter::repeat_n(0, 11 + r.get(7)? as usize)),
                            }
                        }
                        (all[..hlit].to_vec(), all[hlit..].to_vec())
                    };
                    loop {
                        let s = r.decode(&lit)?;
                        if s < 256 {
                            out.push(s as u8);
                        } else if s == 256 {
                            break;
                        } else {
                            let c = s - 257;
                            let l = LEN_BASE[c] as usize + r.get(u32::from(LEN_EXTRA[c]))? as usize;
                            let dc = r.decode(&dist)?;
                            let d =
                                DIST_BASE[dc] as usize + r.get(u32::from(DIST_EXTRA[dc]))? as usize;
                            for _ in 0..l {
                                let b = out[out.len().checked_sub(d)?];
                                out.push(b);
                            }
                        }
                    }
                }
                _ => return None,
            }
            if last == 1 {
                return Some(out);
            }
        }
    }

    #[test]
    fn checksums_match_known_values() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
        assert_eq!(adler32(b"Wikipedia"), 0x11E6_0398);
        assert_eq!(adler32(b""), 1);
        // IEND's CRC
        assert_eq!(crc32(b"IEND"), 0xAE42_6082);
    }

    #[test]
    fn deflate_round_trips() {
        let mut noise = Vec::new();
        let mut x: u32 = 12345;
        for _ in 0..70_000 {
            x = x.wrapping_mul(1_103_515_245).wrapping_add(12345);
            noise.push((x >> 16) as u8);
        }
        let text = b"abcabcabcabcabcabc hello hello hello world ".repeat(500);
        let cases: Vec<Vec<u8>> = vec![
            Vec::new(),
            b"a".to_vec(),
            b"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa".to_vec(),
            text.clone(),
            noise.clone(),
            vec![0u8; 300_000],
            [text, noise].concat(),
        ];
        for d in cases {
            let z = deflate(&d);
            assert_eq!(inflate(&z).as_deref(), Some(&d[..]), "length {}", d.len());
            if d.len() > 1000 && d.iter().all(|&b| b == 0) {
                assert!(z.len() < d.len() / 100);
            }
        }
    }

    #[test]
    fn huffman_lengths_respect_the_limit_and_kraft() {
        // Fibonacci frequencies force long codes
        let mut f = vec![1u32, 1];
        while f.len() < 30 {
            let n = f.len();
            f.push(f[n - 1] + f[n - 2]);
        }
        let l = huffman_lengths(&f, 15);
        assert!(l.iter().all(|&x| (1..=15).contains(&x)));
        let kraft: f64 = l.iter().map(|&x| 0.5f64.powi(i32::from(x))).sum();
        assert!((kraft - 1.0).abs() < 1e-12);
        let one = huffman_lengths(&[0, 0, 5, 0], 15);
        assert_eq!(one.iter().filter(|&&x| x > 0).count(), 2);
    }

    #[test]
    fn png_structure() {
        let px: Vec<u8> = (0..4 * 3 * 3).map(|i| (i * 7) as u8).collect();
        let png = encode_png(4, 3, ColorType::Rgb, &px).expect("valid");
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(&png[12..16], b"IHDR");
        assert_eq!(&png[png.len() - 12..], b"\0\0\0\0IEND\xAE\x42\x60\x82");
        // IDAT → zlib → filtered rows
        let len = u32::from_be_bytes([png[33], png[34], png[35], png[36]]) as usize;
        assert_eq!(&png[37..41], b"IDAT");
        let z = &png[41..41 + len];
        assert_eq!(&z[..2], &[0x78, 0x9C]);
        let raw = inflate(&z[2..z.len() - 4]).expect("inflates");
        assert_eq!(raw.len(), 3 * (1 + 12));
        assert_eq!(
            u32::from_be_bytes([z[len - 4], z[len - 3], z[len - 2], z[len - 1]]),
            adler32(&raw)
        );
        assert!(encode_png(0, 3, ColorType::Rgb, &[]).is_err());
        assert!(encode_png(4, 3, ColorType::Rgba, &px).is_err());
    }
}
