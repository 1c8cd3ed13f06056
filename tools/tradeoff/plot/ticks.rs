//! The ticks of the plot's logarithmic axes: where they go ([`log_ticks`]: round values only,
//! and no more than fit) and how they are written ([`tick_label`]).

/// The ticks of a logarithmic axis from `lo` to `hi` (both > 0): the values 1, 2 and 5 × a
/// power of ten inside the range, or, where more than `max` of those fall inside, 1 and 3 ×,
/// then powers of ten, then every second, third, … power of ten, whichever first gives at most
/// `max` ticks. Increasing; each value is the double nearest its decimal form.
pub fn log_ticks(lo: f64, hi: f64, max: usize) -> Vec<f64> {
    let with = |mantissas: &[u32], every: i32| -> Vec<f64> {
        let (first, last) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
        let mut ticks = Vec::new();
        for k in (first..=last).filter(|k| k.rem_euclid(every) == 0) {
            for m in mantissas {
                // parsed from its decimal form: 3e-1 is the double nearest 0.3, not 3 × 0.1
                let v: f64 = format!("{m}e{k}").parse().expect("a number");
                if (lo..=hi).contains(&v) {
                    ticks.push(v);
                }
            }
        }
        ticks
    };
    for mantissas in [&[1, 2, 5][..], &[1, 3], &[1]] {
        let ticks = with(mantissas, 1);
        if ticks.len() <= max {
            return ticks;
        }
    }
    let mut every = 2;
    loop {
        let ticks = with(&[1], every);
        if ticks.len() <= max.max(1) {
            return ticks;
        }
        every += 1;
    }
}

/// A tick's label: as few decimals as the value needs ("0.5", "2", "100").
pub fn tick_label(v: f64) -> String {
    let decimals = if v >= 1.0 || v <= 0.0 {
        0
    } else {
        (-v.log10().floor()) as usize
    };
    format!("{v:.decimals$}")
}

#[cfg(test)]
mod tests {
    use super::{log_ticks, tick_label};

    #[test]
    fn ticks_at_one_two_five_when_they_fit() {
        assert_eq!(log_ticks(3.0, 150.0, 8), vec![5.0, 10.0, 20.0, 50.0, 100.0]);
        assert_eq!(
            log_ticks(0.35, 40.0, 8),
            vec![0.5, 1.0, 2.0, 5.0, 10.0, 20.0]
        );
    }

    #[test]
    fn fewer_ticks_when_one_two_five_would_crowd() {
        // 1-2-5 over 1 … 1000 gives 10 ticks: 1 and 3 gives 7
        assert_eq!(
            log_ticks(1.0, 1000.0, 8),
            vec![1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0]
        );
        assert_eq!(log_ticks(1.0, 1000.0, 4), vec![1.0, 10.0, 100.0, 1000.0]);
        assert_eq!(log_ticks(1e-3, 1e6, 5), vec![1e-2, 1.0, 1e2, 1e4, 1e6]);
    }

    #[test]
    fn ticks_are_the_doubles_of_their_decimal_form() {
        assert_eq!(log_ticks(0.1, 1.0, 3), vec![0.1, 0.3, 1.0]);
        assert_eq!(
            log_ticks(0.25, 0.35, 8),
            Vec::<f64>::new(),
            "no 1, 2 or 5 × 10ᵏ inside"
        );
    }

    #[test]
    fn labels_have_the_decimals_they_need() {
        assert_eq!(tick_label(0.5), "0.5");
        assert_eq!(tick_label(0.05), "0.05");
        assert_eq!(tick_label(0.3), "0.3");
        assert_eq!(tick_label(2.0), "2");
        assert_eq!(tick_label(100.0), "100");
    }
}
