using System;
using System.Collections.Generic;
using System.Linq;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;

namespace MagnusBall.Presets
{
    /// <summary>
    /// Ready-made balls with published aerodynamics, by sport, and lookup by name
    /// (<see cref="FromName"/>). Every preset cites its sources; where none was found the assumption is
    /// stated. docs/presets.md tabulates them with a sample flight each.
    /// </summary>
    public static class SportPresets
    {
        /// <summary>
        /// Tennis: the library's one tennis ball, <see cref="MagnusBall.Ball.Tennis"/> (57 g, 66 mm diameter, the
        /// ball of Cross (2011) and the seed thesis, inside the ITF's 56.0-59.4 g and 6.54-6.86 cm),
        /// inertia factor 0.55 (Cross 2002, hollow shell of finite thickness); Stepanek's (1988, Am. J. Phys.
        /// 56:138) spin-dependent C_D and C_L; spin decay 2 % per 6.4 m of flight (Cross &amp; Lindsey 2014); bounce: Cross's slide/grip model on a hard
        /// court (<see cref="MagnusBall.Contact.CrossBounce.Hard"/>, Cross 2020).
        /// </summary>
        public static SportPreset Tennis { get; } = new SportPreset(
            "tennis",
            Ball.Tennis,
            StepanekDrag.Instance,
            StepanekLift.Instance,
            SpeedProportionalSpinDecay.TennisCrossLindsey,
            "ball 57 g, 66 mm (Cross 2011; inside ITF Rules of Tennis, appendix I: 56.0-59.4 g, 6.54-6.86 cm); inertia factor 0.55 (Cross 2002); " +
            "Stepanek 1988, Am. J. Phys. 56:138 (C_D, C_L); spin decay 2 % per 6.4 m (Cross & Lindsey 2014); " +
            "bounce: Cross's slide/grip model on a hard court (Cross 2020).",
            CrossBounce.Hard);

        /// <summary>
        /// Tennis with Cross &amp; Lindsey's free-flight drag: the <see cref="Tennis"/> ball and lift, but
        /// C_D = 0.507 (+- 0.024), measured independent of speed and spin for 15-30 m/s and up to 2500 rpm
        /// (Cross &amp; Lindsey 2014).
        /// </summary>
        public static SportPreset TennisFreeFlight { get; } = new SportPreset(
            "tennis-free-flight",
            Tennis.Ball,
            ConstantDrag.CrossLindseyTennis,
            StepanekLift.Instance,
            SpeedProportionalSpinDecay.TennisCrossLindsey,
            "As tennis, but C_D = 0.507 (Cross & Lindsey 2014, free-flight measurements, 15-30 m/s, <= 2500 rpm).",
            CrossBounce.Hard);

        /// <summary>
        /// Soccer: a FIFA size-5 ball (circumference 68-70 cm, mass 410-450 g; 0.43 kg and r = 0.11 m used), thin
        /// shell; Goff &amp; Carre's drag crisis and spin-dependent drag (<see cref="GoffCarreSoccerDrag"/>) and
        /// tabulated lift (<see cref="PiecewiseLinearLift.SoccerGoffCarre"/>). Spin decay: none found in these
        /// sources; constant spin is assumed (a free kick lasts about a second).
        /// </summary>
        public static SportPreset Soccer { get; } = new SportPreset(
            "soccer",
            new Ball(0.43, 0.11, Ball.ThinShellInertiaFactor),
            GoffCarreSoccerDrag.Instance,
            PiecewiseLinearLift.SoccerGoffCarre,
            null,
            "FIFA Laws of the Game, law 2 (size 5: 68-70 cm, 410-450 g); Goff & Carre 2010, Eur. J. Phys. 31:775 " +
            "(drag crisis, Teamgeist lift) and 2009, Am. J. Phys. 77:1020 (spin drag, lift at high S); " +
            "assumption: constant spin (no decay law found).");

        /// <summary>
        /// Baseball: MLB ball (5-5.25 oz, 9-9.25 in circumference; 0.145 kg and r = 0.0366 m used), solid-sphere
        /// inertia 0.4 (assumed); Nathan's C_D = 0.3008 + 0.0292 rpm/1000 and C_L = 1.120 S/(0.583 + 2.333 S)
        /// (<see cref="NathanBaseballDrag"/>, <see cref="NathanBaseballLift"/>); Nathan's (2008) spin-down,
        /// time constant 5 s at 100 mph (<see cref="SpeedProportionalSpinDecay.BaseballNathan"/>).
        /// </summary>
        public static SportPreset Baseball { get; } = new SportPreset(
            "baseball",
            new Ball(0.145, 0.0366, Ball.SolidSphereInertiaFactor),
            NathanBaseballDrag.Instance,
            NathanBaseballLift.Instance,
            SpeedProportionalSpinDecay.BaseballNathan,
            "MLB Official Baseball Rules 3.01 (5-5.25 oz, 9-9.25 in); A. M. Nathan's trajectory calculator " +
            "(C_D, C_L; as ported in pybaseball); Nathan 2008, Am. J. Phys. 76:119 (spin decay, tau 5 s at 100 mph).");

        /// <summary>
        /// Golf: a USGA ball (at most 45.93 g, at least 42.67 mm; those limits used), inertia 0.4 (assumed); drag
        /// rising with spin and a drag crisis in the Reynolds number, lift rising steeply with spin and flattening (a power of the spin parameter below 1)
        /// (<see cref="GolfSpinReynoldsDrag"/>, <see cref="GolfSpinReynoldsLift"/>), the form fitted to Bearman &amp;
        /// Harvey's (1976) wind-tunnel grid, then one constant, the drag floor, refitted once to all 24 shots of a
        /// TrackMan session (<see cref="GolfSpinReynoldsDrag.TrackManCalibrated"/>; the lift is
        /// <see cref="GolfSpinReynoldsLift.BearmanHarvey"/>; docs/presets.md); spin decay 4 %/s (tau = -1/ln 0.96 = 24.5 s):
        /// TrackMan's radar figure, "the spin rate drops during ball flight - typically 4 % for each second" (TrackMan
        /// newsletter, October 2010, as quoted by D. Tutelman, "Spin decay for a ball in flight", 2016; second-hand).
        /// </summary>
        public static SportPreset Golf { get; } = new SportPreset(
            "golf",
            new Ball(0.04593, 0.021335, Ball.SolidSphereInertiaFactor),
            GolfSpinReynoldsDrag.TrackManCalibrated,
            GolfSpinReynoldsLift.BearmanHarvey,
            new ExponentialSpinDecay(GolfSpinDecayTimeConstant),
            "USGA Rules of Golf, equipment appendix (45.93 g, 42.67 mm); C_D(S, Re) and C_L(S, Re) in the form fitted to " +
            "Bearman & Harvey 1976, Aeronautical Quarterly 27:112 (Figs. 7-8), the drag floor refitted to 24 TrackMan shots " +
            "(data/published/golf-trackman-session.json); spin decay 4 %/s (TrackMan).");

        /// <summary>
        /// Golf with the wind-tunnel law as fitted to Bearman &amp; Harvey (1976), uncalibrated: the <see cref="Golf"/>
        /// ball and spin decay with <see cref="GolfSpinReynoldsDrag.BearmanHarvey"/> and
        /// <see cref="GolfSpinReynoldsLift.BearmanHarvey"/>. On the TrackMan session irons and wedges come within 1-3
        /// per cent, drivers 9-11 % short; on the tour averages it is within 1.4 % (median; worst 6.8 %), docs/validation.md.
        /// </summary>
        public static SportPreset GolfBearmanHarvey { get; } = new SportPreset(
            "golf-bearman-harvey",
            Golf.Ball,
            GolfSpinReynoldsDrag.BearmanHarvey,
            GolfSpinReynoldsLift.BearmanHarvey,
            Golf.SpinDecay,
            "As golf, but the C_D(S, Re) and C_L(S, Re) fitted to Bearman & Harvey 1976 (Aeronautical Quarterly 27:112, Figs. 7-8) uncalibrated.");

        /// <summary>
        /// The <c>golf</c> preset as it was before the wind-tunnel law (kept so old scenarios can reproduce their
        /// numbers): Smits &amp; Smith's lift table with C_D = 0.1845 + 0.3533 S, two constants calibrated to the 2023
        /// TrackMan tour driver and 7-iron carries (<see cref="LinearSpinDrag.GolfTrackManCalibrated"/>).
        /// </summary>
        public static SportPreset GolfLinear2023 { get; } = new SportPreset(
            "golf-linear-2023",
            Golf.Ball,
            LinearSpinDrag.GolfTrackManCalibrated,
            PiecewiseLinearLift.GolfSmitsSmith,
            Golf.SpinDecay,
            "The golf preset before issue 12: Smits & Smith 1994 lift table, C_D = 0.1845 + 0.3533 S calibrated to the TrackMan 2023 " +
            "tour driver and 7-iron carries; spin decay 4 %/s.");

        /// <summary>
        /// Golf as published by Smits &amp; Smith (1994), uncalibrated: the <see cref="Golf"/> ball, lift and spin
        /// decay with C_D = 0.24 + 0.18 S (<see cref="LinearSpinDrag.GolfSmitsSmith"/>). It carries the TrackMan
        /// driver about 10 % short (253 yd against 282) and the 7-iron 4 % long (183 yd against 176).
        /// </summary>
        public static SportPreset GolfSmitsSmith { get; } = new SportPreset(
            "golf-smits-smith",
            Golf.Ball,
            LinearSpinDrag.GolfSmitsSmith,
            PiecewiseLinearLift.GolfSmitsSmith,
            Golf.SpinDecay,
            "As golf, but Smits & Smith's own C_D = 0.24 + 0.18 S (Science and Golf II, 1994; secondary transcription).");

        /// <summary>
        /// Table tennis: ITTF ball (40 mm, 2.7 g), thin shell. C_D(speed, S) and C_L(speed, |w|) of a 40 mm ball after
        /// Conti et al. (2026, arXiv:2606.28805), fitted to recorded table-tennis flights; <b>second-hand</b>: the paper's
        /// table as transcribed in two public repositories that agree (data/coefficients/README.md). C_D 0.47-0.55 without
        /// spin, 0.37-0.55 with it; C_L = (8/3) C_M S with the valley near S 0.5-1 that Miyazaki et al. (2017) measured in
        /// flight (the lift crisis). Valid 2-17 m/s, spins up to about 1000 rad/s. Spin decay: not measured for a table-tennis
        /// ball; Cross &amp; Lindsey's (2014) tennis torque coefficient scaled to this ball's radius and inertia
        /// (dw/dt = -k s w with k proportional to r^4 / I: k = 0.0202 per metre, 2 % of the spin per metre of flight),
        /// an assumption the docs state (docs/presets.md).
        /// </summary>
        public static SportPreset TableTennis { get; } = new SportPreset(
            "table-tennis",
            new Ball(0.0027, 0.020, Ball.ThinShellInertiaFactor),
            ContiTableTennisDrag.Instance,
            ContiTableTennisLift.Instance,
            new SpeedProportionalSpinDecay(TableTennisSpinDecayPerMetre),
            "ITTF Handbook 2.3 (40 mm, 2.7 g). C_D and C_L: Conti et al. 2026, arXiv:2606.28805 (fitted to recorded table-tennis flights; " +
            "second-hand transcription, data/coefficients/). Assumption: spin decay Cross & Lindsey 2014's tennis torque scaled to the " +
            "ball's r^4/I (not measured for table tennis).");

        /// <summary>
        /// Table-tennis spin decay k, 1/m: Cross &amp; Lindsey's tennis k = -ln(0.98)/6.4 m (57 g, r 33 mm, inertia factor
        /// 0.55) scaled by r^4 / I, the ratio a torque 1/2 rho A r C s^2 with C proportional to S gives (the form of
        /// <see cref="SpeedProportionalSpinDecay"/>): 0.003157 x (0.02^2 / (2/3 x 0.0027)) / (0.033^2 / (0.55 x 0.057)).
        /// </summary>
        internal const double TableTennisSpinDecayPerMetre = 0.0031566730183624162 * (0.02 * 0.02 / (2.0 / 3.0 * 0.0027)) / (0.033 * 0.033 / (0.55 * 0.057));

        /// <summary>
        /// Basketball: FIBA size 7 (circumference 749-780 mm, 567-650 g; 0.6 kg and r = 0.1205 m used), thin
        /// shell. C_D = 0.54: <b>not traced to a measurement</b>; the earliest use found quotes it without a source
        /// (Schutzengel, Varin &amp; Quinlivan, "The Physics of a Three Point Shot", University Physics Competition 2011:
        /// "found in literature to be 0.54"; read second-hand). No measured C_D or C_L of a basketball could be read
        /// here (docs/presets.md, "Not yet traced"). Stated assumptions: lift from Stepanek's saturating curve (borrowed
        /// from tennis) and constant spin (a shot lasts about a second).
        /// </summary>
        public static SportPreset Basketball { get; } = new SportPreset(
            "basketball",
            new Ball(0.60, 0.1205, Ball.ThinShellInertiaFactor),
            new ConstantDrag(0.54),
            StepanekLift.Instance,
            null,
            "FIBA Official Basketball Rules, equipment (size 7). C_D = 0.54 unsourced (quoted without a source by Schutzengel, Varin & Quinlivan 2011), not a measurement. " +
            "Assumptions: C_L from Stepanek's tennis curve; constant spin.");

        /// <summary>Golf spin-decay time constant, s: 4 %/s, tau = -1/ln(0.96) = 24.5 s.</summary>
        internal const double GolfSpinDecayTimeConstant = 24.496;

        /// <summary>Every preset, in the order of <see cref="Names"/>.</summary>
        public static IReadOnlyList<SportPreset> All { get; } = Array.AsReadOnly(new[]
        {
            Tennis, TennisFreeFlight, Soccer, Baseball, Golf, GolfSmitsSmith, TableTennis, Basketball, GolfBearmanHarvey, GolfLinear2023,
        });

        /// <summary>The names <see cref="FromName"/> accepts.</summary>
        public static IReadOnlyList<string> Names { get; } = Array.AsReadOnly(All.Select(p => p.Name).ToArray());

        /// <summary>
        /// The preset called <paramref name="name"/>: case-insensitive, with '_' or ' ' accepted for '-'
        /// ("table-tennis", "Table_Tennis" and "table tennis" are the same).
        /// </summary>
        /// <param name="name">One of <see cref="Names"/>.</param>
        /// <exception cref="ArgumentException">The name is null or unknown; the message lists the known names.</exception>
        public static SportPreset FromName(string name)
        {
            foreach (SportPreset preset in All)
            {
                if (NameLookup.Matches(preset.Name, name))
                {
                    return preset;
                }
            }

            throw new ArgumentException(
                $"name must be one of: {string.Join(", ", Names)}; got '{name ?? "null"}'.", nameof(name));
        }
    }
}
