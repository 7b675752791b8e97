//! The C ABI's references and ensemble mean (issue 78): the values of the theory crate for a
//! configuration, flagged where not computable, refused with a message where asked wrongly;
//! the mean and interval of the statistics kit to the bit.

use gdsmc::{
    GDSMC_REFERENCE_LIMIT, GDSMC_REFERENCE_MEAN_AT_N, gdsmc_config, gdsmc_config_default,
    gdsmc_last_error, gdsmc_mean, gdsmc_mean_add, gdsmc_mean_interval, gdsmc_reference,
    gdsmc_reference_count, gdsmc_reference_find, gdsmc_reference_get, gdsmc_status,
};
use std::ffi::{CStr, CString};

fn config() -> gdsmc_config {
    let mut c = std::mem::MaybeUninit::<gdsmc_config>::uninit();
    // SAFETY: a writable config.
    assert_eq!(
        unsafe { gdsmc_config_default(c.as_mut_ptr()) },
        gdsmc_status::GDSMC_OK
    );
    // SAFETY: written by gdsmc_config_default.
    unsafe { c.assume_init() }
}

fn last_error() -> String {
    let mut buf = vec![0u8; 512];
    // SAFETY: a writable buffer of its length.
    let len = unsafe { gdsmc_last_error(buf.as_mut_ptr().cast(), buf.len()) };
    String::from_utf8(buf[..len].to_vec()).unwrap()
}

fn find(c: &gdsmc_config, times: &[f64], name: &str) -> (gdsmc_status, gdsmc_reference, Vec<f64>) {
    let name = CString::new(name).unwrap();
    let mut r = std::mem::MaybeUninit::<gdsmc_reference>::zeroed();
    let mut v = vec![0.0; times.len()];
    // SAFETY: valid pointers of the stated lengths.
    let s = unsafe {
        gdsmc_reference_find(
            c,
            times.as_ptr(),
            times.len(),
            name.as_ptr(),
            r.as_mut_ptr(),
            v.as_mut_ptr(),
        )
    };
    // SAFETY: zeroed is a valid gdsmc_reference (null pointers, zeros).
    (s, unsafe { r.assume_init() }, v)
}

fn text(p: *const std::ffi::c_char) -> String {
    // SAFETY: gdsmc's static NUL-terminated strings.
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}

/// GRW Example 3's references through C: GRW (13) in its closed form (T_inf = 8/3, rate
/// 3/4, to rounding), the exact mean at n as the theory crate gives it (to the bit), every
/// reference listed by count and get.
#[test]
fn the_references_of_a_configuration_are_the_theorys() {
    let mut c = config();
    c.n = 4096;
    let times: Vec<f64> = (0..=8).map(f64::from).collect();
    let (s, r, v) = find(&c, &times, "T_exact");
    assert_eq!(s, gdsmc_status::GDSMC_OK, "{}", last_error());
    assert_eq!((text(r.name), text(r.of)), ("T_exact".into(), "T".into()));
    assert_eq!((r.kind, r.not_computable), (GDSMC_REFERENCE_LIMIT, 0));
    for (t, x) in times.iter().zip(&v) {
        let want = 8.0 / 3.0 + (1.0 - 8.0 / 3.0) * libm::exp(-0.75 * t);
        assert!((x - want).abs() <= 1e-14 * want, "t = {t}: {x} vs {want}");
    }
    let (s, r, at_n) = find(&c, &times, "T_mean_n");
    assert_eq!(
        (s, r.kind),
        (gdsmc_status::GDSMC_OK, GDSMC_REFERENCE_MEAN_AT_N)
    );
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml");
    let mut scene = gdsmc_scene::parse(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
    scene.set_n(4096).unwrap();
    scene.set_times(times.clone()).unwrap();
    let theory = gdsmc_theory::curves::for_scene(&scene);
    let mean = theory.iter().find(|r| r.name == "T_mean_n").unwrap();
    for (t, x) in times.iter().zip(&at_n) {
        assert_eq!(x.to_bits(), (mean.curve)(*t).to_bits(), "t = {t}");
    }
    let mut count = 0;
    // SAFETY: valid pointers.
    let s = unsafe { gdsmc_reference_count(&c, times.as_ptr(), times.len(), &mut count) };
    assert_eq!((s, count), (gdsmc_status::GDSMC_OK, theory.len()));
    for (k, want) in theory.iter().enumerate() {
        let mut r = std::mem::MaybeUninit::<gdsmc_reference>::zeroed();
        let mut v = vec![0.0; times.len()];
        // SAFETY: valid pointers of the stated lengths.
        let s = unsafe {
            gdsmc_reference_get(
                &c,
                times.as_ptr(),
                times.len(),
                k,
                r.as_mut_ptr(),
                v.as_mut_ptr(),
            )
        };
        assert!(s == gdsmc_status::GDSMC_OK || s == gdsmc_status::GDSMC_NOT_COMPUTABLE);
        // SAFETY: written by the call.
        assert_eq!(text(unsafe { r.assume_init() }.name), want.name);
    }
}

/// Where a reference's arithmetic cannot hold (Bobylev et al.'s a2(t) at a collision rate of
/// 1e-300) the call says so: GDSMC_NOT_COMPUTABLE, the count of such times, NaN there, a
/// message naming it; a reference that does not hold is GDSMC_NOT_FOUND naming those that do;
/// bad times and indices are refused with their names.
#[test]
fn what_cannot_be_computed_or_does_not_hold_is_said() {
    let mut c = config();
    c.gamma = 1e-300;
    let times = [0.0, 1.0, 2.0];
    let (s, r, v) = find(&c, &times, "a2_exact");
    assert_eq!(s, gdsmc_status::GDSMC_NOT_COMPUTABLE);
    assert_eq!(r.not_computable, 3);
    assert!(v.iter().all(|x| x.is_nan()));
    assert!(
        last_error().contains("a2_exact is not computable here"),
        "{}",
        last_error()
    );
    let (s, _, v) = find(&c, &times, "T_exact");
    assert_eq!(s, gdsmc_status::GDSMC_OK);
    assert_eq!(v, [1.0, 3.0, 5.0]);

    let (s, _, _) = find(&config(), &times, "T_bulk_sonine");
    assert_eq!(s, gdsmc_status::GDSMC_NOT_FOUND);
    let m = last_error();
    assert!(
        m.contains("no reference `T_bulk_sonine`") && m.contains("T_mean_n"),
        "{m}"
    );

    let (s, _, _) = find(&config(), &[0.0, 2.0, 1.0], "T_exact");
    assert_eq!(s, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    assert!(last_error().contains("times"), "{}", last_error());
    let mut r = std::mem::MaybeUninit::<gdsmc_reference>::zeroed();
    let mut v = [0.0; 3];
    // SAFETY: valid pointers of the stated lengths.
    let s = unsafe {
        gdsmc_reference_get(
            &config(),
            times.as_ptr(),
            3,
            99,
            r.as_mut_ptr(),
            v.as_mut_ptr(),
        )
    };
    assert_eq!(s, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    assert!(last_error().contains("`index` = 99"), "{}", last_error());
    // SAFETY: a null config is refused before it is read.
    let s = unsafe {
        gdsmc_reference_get(
            std::ptr::null(),
            times.as_ptr(),
            3,
            0,
            r.as_mut_ptr(),
            v.as_mut_ptr(),
        )
    };
    assert_eq!(s, gdsmc_status::GDSMC_NULL_POINTER);
}

/// gdsmc_mean is the statistics kit's accumulator: the same mean and interval to the bit as
/// `gdsmc_stats::Accumulator` fed in the same order (the command's), refusing a non-finite
/// value and an interval of fewer than two.
#[test]
fn the_mean_is_the_kits_to_the_bit() {
    let xs: Vec<f64> = (0..40)
        .map(|k| 2.0 + ((k * 7919) % 97) as f64 / 31.0)
        .collect();
    let mut acc = gdsmc_mean::default();
    let mut kit = gdsmc_stats::Accumulator::new(1);
    let (mut mean, mut half) = (0.0, 0.0);
    // SAFETY: valid pointers.
    let s = unsafe { gdsmc_mean_interval(&acc, &mut mean, &mut half) };
    assert_eq!(s, gdsmc_status::GDSMC_INVALID_ARGUMENT);
    for &x in &xs {
        // SAFETY: a valid accumulator.
        assert_eq!(
            unsafe { gdsmc_mean_add(&mut acc, x) },
            gdsmc_status::GDSMC_OK
        );
        kit.push(&[x]);
    }
    // SAFETY: a valid accumulator.
    assert_eq!(
        unsafe { gdsmc_mean_add(&mut acc, f64::NAN) },
        gdsmc_status::GDSMC_NON_FINITE
    );
    // SAFETY: valid pointers.
    let s = unsafe { gdsmc_mean_interval(&acc, &mut mean, &mut half) };
    assert_eq!(s, gdsmc_status::GDSMC_OK);
    assert_eq!(acc.count, 40);
    assert_eq!(mean.to_bits(), kit.mean(0).to_bits());
    assert_eq!(half.to_bits(), kit.ci(0).to_bits());
    // At 40 values the multiplier is Student's t of 39 dof at 3.2 sigma's level: 3.446.
    assert!((gdsmc_stats::multiplier(40) - 3.446).abs() < 5e-4);
}
