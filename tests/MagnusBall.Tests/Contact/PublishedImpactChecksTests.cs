using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Swings;
using MagnusBall.Queries;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>
    /// The published checks of docs/impacts.md that the first version of the helpers did not meet: the 7-iron's
    /// ball speed (now a two-sided check with a sourced iron head mass and COR), the driver's tour spin (out of
    /// reach of the rigid contact, with a point-mass head and with the measured head rotating: shown, not tuned), and
    /// the hand-held racket's spin loss (which case the model is, and what it gives in each regime).
    /// </summary>
    [TestFixture]
    public class PublishedImpactChecksTests
    {
        private const double Mph = 0.44704;

        // The golf ball of the golf preset (src/MagnusBall/Runtime/Presets/SportPresets.cs).
        private static readonly Ball Golf = new Ball(0.04593, 0.021335, Ball.SolidSphereInertiaFactor);
        private static readonly LaunchFrame ZUp = new LaunchFrame(Vector3d.UnitZ, Vector3d.UnitX);

        /// <summary>A 7-iron head, kg: Maltby's standard 5-iron head of 254 g plus 7 g per club (ralphmaltby.com, "weight parameters for club head").</summary>
        private const double SevenIronHeadMass = 0.268;

        [TestCase(0.76)]
        [TestCase(0.77)]
        public void SevenIron_TourAverage_BallSpeed(double restitution)
        {
            // TrackMan PGA Tour averages (older table, docs/references.md 5a): 7-iron, 90 mph club, attack -4.3 deg,
            // 120 mph ball, 16.3 deg launch, 7097 rpm. Iron COR: "about .760" for most irons (Langmead 2007, PGA
            // professional) and "in the area of 0.77" for cast irons (Wishon, via bobsailergolf 2011): both ends tested.
            // The dynamic loft is not published: it is the loft that gives the published launch angle.
            double loft = LoftForLaunch(90 * Mph, -4.3, SevenIronHeadMass, restitution, 16.3);
            SwingLaunch l = new ClubSwing(90 * Mph, loft, -4.3, headMass: SevenIronHeadMass, restitution: restitution).Hit(Golf, ZUp, Vector3d.Zero);
            TestContext.Out.WriteLine($"7-iron e {restitution}: loft {loft:F2} deg -> {l.Speed / Mph:F2} mph, launch {l.ElevationDegrees:F2} deg, {l.SpinRpm:F0} rpm");
            // Tolerance, an error budget of the inputs: the head 261-275 g (one club's 7 g either way: 0.8 %), the COR
            // 0.76 vs 0.77 (0.6 %), the 120 mph rounded to the mph (0.4 %), and the tangential restitution the helper
            // leaves at 0: the published spin (7097 rpm) is matched with e_x = 0.26 at the published launch, which takes
            // the ball speed 1.2 % lower (SevenIron_PublishedLaunchAndSpin_AreMatchedWithATangentialRestitution). 3 % in all.
            Assert.That(l.Speed / Mph, Is.EqualTo(120).Within(0.03 * 120));
        }

        [Test]
        public void SevenIron_PublishedLaunchAndSpin_AreMatchedWithATangentialRestitution()
        {
            // The rigid contact with e_x = 0 (the ball leaves rolling on the face) gives 5286 rpm at the published 16.3 deg
            // launch, 26 % under the 7097 rpm measured. Cross's grip recoil e_x > 0 raises the spin at a given launch: solve
            // e_x and the loft for both published numbers at once and report them (docs/impacts.md); e_x must come out in
            // Cross's range [0, 1] for the law to explain the iron's spin.
            const double e = 0.765;
            double lo = 0, hi = 1;
            for (int i = 0; i < 100 && hi - lo > 1e-9; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (HitWithRecoil(90 * Mph, LoftForLaunch(90 * Mph, -4.3, SevenIronHeadMass, e, 16.3, mid), -4.3, SevenIronHeadMass, e, mid).SpinRpm < 7097)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            double ex = 0.5 * (lo + hi);
            double loft = LoftForLaunch(90 * Mph, -4.3, SevenIronHeadMass, e, 16.3, ex);
            SwingLaunch l = HitWithRecoil(90 * Mph, loft, -4.3, SevenIronHeadMass, e, ex);
            TestContext.Out.WriteLine($"7-iron: e_x {ex:F3}, loft {loft:F2} deg -> {l.Speed / Mph:F2} mph, {l.ElevationDegrees:F2} deg, {l.SpinRpm:F0} rpm");
            Assert.That(ex, Is.GreaterThan(0.05).And.LessThan(1)); // inside Cross's range, not at its edge
            Assert.That(l.SpinRpm, Is.EqualTo(7097).Within(1));   // the bisection's resolution
            // With the spin matched, the speed is a check again: the same 3 % budget without its e_x share (1.8 %).
            Assert.That(l.Speed / Mph, Is.EqualTo(120).Within(0.018 * 120));
        }

        [Test]
        public void Driver_TourSpin_IsOutOfReachOfTheRigidContact_AtThePublishedLaunch()
        {
            // USGA/R&A 2015 PGA Tour drives: 113.2 mph club, 10.8 deg launch, 2599 rpm (attack -1.3 deg, TrackMan). At the
            // published launch the rigid contact gives 3886 rpm (+50 %). Neither contact parameter brings it down:
            // friction above the grip threshold changes nothing (the ball grips and leaves rolling), and the grip
            // recoil e_x in Cross's range [0, 1] only raises the spin at a given launch. So the gap is not a coefficient
            // to tune. The head's rotation (Driver_TourSpin_StaysOutOfReach_WithTheMeasuredHeadsRotation) lowers it but does
            // not close the gap either.
            double previous = 0;
            foreach (double ex in new[] { 0.0, 0.25, 0.5, 0.75, 1.0 })
            {
                double loft = LoftForLaunch(113.2 * Mph, -1.3, ClubSwing.DriverHeadMass, ClubSwing.UsgaLimitRestitution, 10.8, ex);
                double rpm = HitWithRecoil(113.2 * Mph, loft, -1.3, ClubSwing.DriverHeadMass, ClubSwing.UsgaLimitRestitution, ex).SpinRpm;
                TestContext.Out.WriteLine($"driver e_x {ex}: loft {loft:F2} deg, {rpm:F0} rpm");
                Assert.That(rpm, Is.GreaterThan(previous));
                Assert.That(rpm, Is.GreaterThan(1.4 * 2599), "at least 40 % over the tour average whatever e_x");
                previous = rpm;
            }

            double gripLoft = LoftForLaunch(113.2 * Mph, -1.3, ClubSwing.DriverHeadMass, ClubSwing.UsgaLimitRestitution, 10.8);
            SwingLaunch reference = new ClubSwing(113.2 * Mph, gripLoft, -1.3).Hit(Golf, ZUp, Vector3d.Zero);
            foreach (double mu in new[] { 0.05, 0.1, 0.4, 1.0 })
            {
                SwingLaunch l = new ClubSwing(113.2 * Mph, gripLoft, -1.3, friction: mu).Hit(Golf, ZUp, Vector3d.Zero);
                Assert.That(l.Impact.Regime, Is.EqualTo(BounceRegime.Grip), $"mu {mu}");
                Assert.That(l.SpinRpm, Is.EqualTo(reference.SpinRpm).Within(1e-9 * reference.SpinRpm), $"mu {mu}");
            }

            // Only a friction below the grip threshold (about 0.048 here, a sliding ball) would lower it, and 2599 rpm
            // needs mu about 0.032: far under any measured ball-face friction.
            SwingLaunch slipping = new ClubSwing(113.2 * Mph, gripLoft, -1.3, friction: 0.032).Hit(Golf, ZUp, Vector3d.Zero);
            TestContext.Out.WriteLine($"driver mu 0.032: {slipping.SpinRpm:F0} rpm, {slipping.Impact.Regime}");
            Assert.That(slipping.Impact.Regime, Is.EqualTo(BounceRegime.Slide));
            Assert.That(slipping.SpinRpm, Is.EqualTo(2599).Within(150));
        }

        /// <summary>
        /// The driver head measured in Table 1 of "Adjusting a Momentum-Based Golf Clubhead-Ball Impact Model to Improve
        /// Accuracy" (University of Waterloo and Ping, Proceedings 2020, 49(1), 47): 204 g, the CG 42.3 mm behind the face
        /// centre along the face normal and 2.9 and 1 mm off it in the face plane, principal moments 2843, 5679 and 4085 g cm^2.
        /// 5679 is taken about the axis up the face (the largest moment of a driver is about the near-vertical axis); which
        /// of the other two is about the heel-toe axis, and which way the 2.9 mm points, the table does not say here: both
        /// readings are the input range below.
        /// </summary>
        private static ClubHead MeasuredDriver(double impactHeight, bool heelToeIs4085) => heelToeIs4085
            ? new ClubHead(0.204, 0.0423, impactHeight, 4.085e-4, 5.679e-4, 2.843e-4)
            : new ClubHead(0.204, 0.0423, impactHeight, 2.843e-4, 5.679e-4, 4.085e-4);

        private static double RigidLoftForLaunch(double speed, double attack, ClubHead head, double launchDegrees, double e = ClubSwing.UsgaLimitRestitution)
        {
            // As LoftForLaunch, with a rigid head: bisection to 1e-10 deg.
            double lo = -5, hi = 60;
            for (int i = 0; i < 60 && hi - lo > 1e-10; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (new ClubSwing(speed, mid, attack, 0, 0, head, e).Hit(Golf, ZUp, Vector3d.Zero).ElevationDegrees < launchDegrees)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            return 0.5 * (lo + hi);
        }

        private static SwingLaunch RigidDriveAtThePublishedLaunch(ClubHead head) =>
            new ClubSwing(113.2 * Mph, RigidLoftForLaunch(113.2 * Mph, -1.3, head, 10.8), -1.3, 0, 0, head).Hit(Golf, ZUp, Vector3d.Zero);

        [Test]
        public void Driver_TourSpin_StaysOutOfReach_WithTheMeasuredHeadsRotation()
        {
            // USGA/R&A 2015: 113.2 mph, attack -1.3 deg, 10.8 deg launch, 2599 rpm; the point-mass head gives 3886 rpm there.
            // With the measured head rotating about its CG (ClubHead), at the published launch, over the input range: the
            // impact on the CG's projection or 2.9 mm either side of it (the paper's in-face CG offset), and either reading
            // of the heel-toe moment (2843 or 4085 g cm^2).
            // The table docs/impacts.md prints (rpm, mph), by heel-toe reading and impact height -2.9, 0, +2.9 mm.
            double[,] tableRpm = { { 3995, 3648, 3302 }, { 4037, 3552, 3067 } };
            double[,] tableMph = { { 163.56, 163.75, 163.70 }, { 163.53, 163.79, 163.72 } };
            double[] heights = { -0.0029, 0.0, 0.0029 };
            double lowest = double.PositiveInfinity, highest = 0;
            for (int row = 0; row < 2; row++)
            {
                bool heelToeIs4085 = row == 0;
                for (int column = 0; column < 3; column++)
                {
                    double height = heights[column];
                    SwingLaunch l = RigidDriveAtThePublishedLaunch(MeasuredDriver(height, heelToeIs4085));
                    TestContext.Out.WriteLine(FormattableString.Invariant(
                        $"heel-toe {(heelToeIs4085 ? 4085 : 2843)} g cm^2, impact {height * 1000:F1} mm above the CG projection: {l.Speed / Mph:F2} mph, {l.SpinRpm:F0} rpm, {l.Impact.Regime}"));
                    Assert.That(l.Impact.Regime, Is.EqualTo(BounceRegime.Grip));
                    lowest = Math.Min(lowest, l.SpinRpm);
                    highest = Math.Max(highest, l.SpinRpm);
                    // The ball speed stays within the driver's 3 % input budget (Driver_TourAverage_BallSpeed) of 167.7 mph.
                    Assert.That(l.Speed / Mph, Is.EqualTo(167.7).Within(0.03 * 167.7));
                    // The docs' table, to its rounding (the rpm, 0.01 mph).
                    Assert.That(l.SpinRpm, Is.EqualTo(tableRpm[row, column]).Within(0.5), $"row {row}, column {column}");
                    Assert.That(l.Speed / Mph, Is.EqualTo(tableMph[row, column]).Within(0.005), $"row {row}, column {column}");
                }
            }

            // On the CG's projection the rotation takes spin off (friction along the face turns the head, 42 mm of lever),
            // but over the whole input range the spin stays at least 15 % over the tour's: not met.
            SwingLaunch centred = RigidDriveAtThePublishedLaunch(MeasuredDriver(0, true));
            Assert.That(centred.SpinRpm, Is.LessThan(3886 * 0.96));
            Assert.That(lowest, Is.GreaterThan(1.15 * 2599), "the input range's lowest spin");
            TestContext.Out.WriteLine($"range {lowest:F0}-{highest:F0} rpm");
            // The range docs/impacts.md and the CHANGELOG print, the table's extremes.
            Assert.That(lowest, Is.EqualTo(3067).Within(0.5));
            Assert.That(highest, Is.EqualTo(4037).Within(0.5));

            // What it would take: the impact height above the CG's projection that gives 2599 rpm (the spin falls as the
            // impact rises: the vertical gear effect). It lies outside the measured head's +-2.9 mm.
            foreach (bool heelToeIs4085 in new[] { true, false })
            {
                double lo = 0, hi = 0.03;
                for (int i = 0; i < 50; i++)
                {
                    double mid = 0.5 * (lo + hi);
                    if (RigidDriveAtThePublishedLaunch(MeasuredDriver(mid, heelToeIs4085)).SpinRpm > 2599)
                    {
                        lo = mid;
                    }
                    else
                    {
                        hi = mid;
                    }
                }

                TestContext.Out.WriteLine(FormattableString.Invariant(
                    $"heel-toe {(heelToeIs4085 ? 4085 : 2843)} g cm^2: 2599 rpm needs the impact {lo * 1000:F2} mm above the CG projection"));
                Assert.That(lo, Is.GreaterThan(0.0029 * 1.5));
                // The heights docs/impacts.md prints (8.85 and 5.72 mm), to their rounding to 0.01 mm.
                Assert.That(lo, Is.EqualTo(heelToeIs4085 ? 0.00885 : 0.00572).Within(0.000005));
            }
        }

        [Test]
        public void SevenIron_HeadRotation_ChangesLittle_ForAShallowCg()
        {
            // No sourced CG depth or heel-toe moment was found for an iron, so the 7-iron stays a point mass. Bound what the
            // rotation could do with assumed values (not measurements): a CG up to 10 mm behind the face (an iron is a thin
            // blade; its CG is "close behind the face") and a heel-toe moment of at least 1000 g cm^2 (a quarter of the
            // driver's 4085), at the CG's projection. The spin then falls by the closed-form factor
            // K_tt(point)/K_tt(rigid) at a fixed delivery, at most 1.3 % here, and at the published 16.3 deg launch the speed
            // and spin stay within the checks' budgets (SevenIron_TourAverage_BallSpeed: 3 %).
            const double e = 0.765;
            var head = new ClubHead(SevenIronHeadMass, 0.010, 0, 1e-4, 2e-4, 1e-4);
            double pointLoft = LoftForLaunch(90 * Mph, -4.3, SevenIronHeadMass, e, 16.3);
            SwingLaunch point = new ClubSwing(90 * Mph, pointLoft, -4.3, headMass: SevenIronHeadMass, restitution: e).Hit(Golf, ZUp, Vector3d.Zero);
            SwingLaunch sameDelivery = new ClubSwing(90 * Mph, pointLoft, -4.3, 0, 0, head, e).Hit(Golf, ZUp, Vector3d.Zero);
            double compliance = (1 + 1 / Golf.InertiaFactor) / Golf.Mass + 1 / SevenIronHeadMass;
            double factor = compliance / (compliance + 0.010 * 0.010 / 1e-4);
            Assert.That(sameDelivery.SpinRpm / point.SpinRpm, Is.EqualTo(factor).Within(1e-10));
            Assert.That(1 - factor, Is.LessThan(0.013));

            double rigidLoft = RigidLoftForLaunch(90 * Mph, -4.3, head, 16.3, e);
            SwingLaunch rigid = new ClubSwing(90 * Mph, rigidLoft, -4.3, 0, 0, head, e).Hit(Golf, ZUp, Vector3d.Zero);
            TestContext.Out.WriteLine(FormattableString.Invariant(
                $"7-iron point mass: loft {pointLoft:F2}, {point.Speed / Mph:F2} mph, {point.SpinRpm:F0} rpm; rigid (10 mm, 1000 g cm^2): loft {rigidLoft:F2}, {rigid.Speed / Mph:F2} mph, {rigid.SpinRpm:F0} rpm; fixed-delivery factor {factor:F4}"));
            Assert.That(rigid.Speed / Mph, Is.EqualTo(120).Within(0.03 * 120));
            Assert.That(rigid.SpinRpm, Is.EqualTo(point.SpinRpm).Within(0.03 * point.SpinRpm));
            // The numbers docs/impacts.md prints (122.88 mph, 5206 rpm; the point mass 122.82 mph, 5286 rpm), to their rounding.
            Assert.That(rigid.Speed / Mph, Is.EqualTo(122.88).Within(0.005));
            Assert.That(rigid.SpinRpm, Is.EqualTo(5206).Within(0.5));
            Assert.That(point.Speed / Mph, Is.EqualTo(122.82).Within(0.005));
            Assert.That(point.SpinRpm, Is.EqualTo(5286).Within(0.5));
        }

        [Test]
        public void VerticalGearEffect_TheSpinFallsAsTheImpactRises()
        {
            // The sign of the vertical gear effect (Tutelman, "All about gear effect - 2a", 2013: a centre hit with the CG level
            // with the face centre gets about 825 rpm more backspin; higher impacts less): with the measured head at a fixed
            // delivery (113.2 mph, loft 13.5 deg, attack -1.3 deg), the spin falls and the launch rises monotonically with
            // the impact's height above the CG's projection; a CG level with the impact point (42.3 mm straight back, the
            // impact 42.3 sin(loft) mm below the CG's projection) gives more spin than the point-mass head.
            double previousSpin = double.PositiveInfinity, previousLaunch = double.NegativeInfinity;
            for (double height = -0.012; height <= 0.0120001; height += 0.001)
            {
                SwingLaunch l = new ClubSwing(113.2 * Mph, 13.5, -1.3, 0, 0, MeasuredDriver(height, true)).Hit(Golf, ZUp, Vector3d.Zero);
                Assert.That(l.SpinRpm, Is.LessThan(previousSpin), $"{height * 1000:F0} mm");
                Assert.That(l.ElevationDegrees, Is.GreaterThan(previousLaunch), $"{height * 1000:F0} mm");
                previousSpin = l.SpinRpm;
                previousLaunch = l.ElevationDegrees;
            }

            double loft = 13.5 * Math.PI / 180;
            var level = new ClubHead(0.204, 0.0423 * Math.Cos(loft), -0.0423 * Math.Sin(loft), 4.085e-4, 5.679e-4, 2.843e-4);
            SwingLaunch behind = new ClubSwing(113.2 * Mph, 13.5, -1.3, 0, 0, level).Hit(Golf, ZUp, Vector3d.Zero);
            SwingLaunch point = new ClubSwing(113.2 * Mph, 13.5, -1.3, headMass: 0.204).Hit(Golf, ZUp, Vector3d.Zero);
            TestContext.Out.WriteLine($"CG level with the impact: {behind.SpinRpm:F0} rpm; point mass {point.SpinRpm:F0} rpm");
            Assert.That(behind.SpinRpm, Is.GreaterThan(point.SpinRpm));
            // The numbers docs/impacts.md prints (4642 against 3883 rpm), to their rounding to the rpm.
            Assert.That(behind.SpinRpm, Is.EqualTo(4642).Within(0.5));
            Assert.That(point.SpinRpm, Is.EqualTo(3883).Within(0.5));

            // The size against Tutelman's "Placement of Center of Gravity" (2013): at 100 mph, 0.1 in (2.54 mm) of CG height
            // is worth 350-400 rpm. His is a model too (an oblate-spheroid estimate of the moment, the force along the launch
            // direction), so only the order is checked: within a factor 2 of his band.
            foreach (bool heelToeIs4085 in new[] { true, false })
            {
                double centred = new ClubSwing(100 * Mph, 13.5, -1.3, 0, 0, MeasuredDriver(0, heelToeIs4085)).Hit(Golf, ZUp, Vector3d.Zero).SpinRpm;
                double raised = new ClubSwing(100 * Mph, 13.5, -1.3, 0, 0, MeasuredDriver(0.00254, heelToeIs4085)).Hit(Golf, ZUp, Vector3d.Zero).SpinRpm;
                TestContext.Out.WriteLine($"100 mph, heel-toe {(heelToeIs4085 ? 4085 : 2843)} g cm^2: {centred:F0} -> {raised:F0} rpm for 2.54 mm ({centred - raised:F0} rpm)");
                Assert.That(centred - raised, Is.InRange(350.0 / 2, 400.0 * 2));
                // The differences docs/impacts.md prints (222 and 312 rpm), to their rounding to the rpm.
                Assert.That(centred - raised, Is.EqualTo(heelToeIs4085 ? 222 : 312).Within(0.5));
            }
        }

        [Test]
        public void Driver_DroppingTheProductsOfInertia_ChangesTheSpinLittle()
        {
            // ClubHead takes principal moments along the face's axes and drops the table's products of inertia (-733, 530.2 and
            // 0.5 g cm^2; docs/references.md). Here the full tensor, in the reading ClubHead.MeasuredDriver takes (the table's
            // axes: face normal 2843, up the face 5679, heel-toe 4085), is diagonalised and given to the rigid law as principal
            // axes, for each sign of the two large products (the table's axis directions are not known here), at the published
            // launch. Dropping them changes the spin by less than 0.5 % (docs/impacts.md prints the largest change), far inside
            // the 18 % by which the tour's 2599 rpm is missed; with the products set to zero this path is ClubSwing's to 1e-6 rpm.
            double[] heights = { -0.0029, 0.0, 0.0029 };
            double largest = 0, largestRpm = 0, largestTilt = 0;
            foreach (double height in heights)
            {
                double diagonal = DriverWithTensorAtThePublishedLaunch(height, 0, 0).SpinRpm;
                Assert.That(diagonal, Is.EqualTo(RigidDriveAtThePublishedLaunch(MeasuredDriver(height, true)).SpinRpm).Within(1e-6));
                foreach (double xy in new[] { -733.0, 733.0 })
                {
                    foreach (double xz in new[] { -530.2, 530.2 })
                    {
                        SwingLaunch full = DriverWithTensorAtThePublishedLaunch(height, xy, xz);
                        TestContext.Out.WriteLine(FormattableString.Invariant(
                            $"impact {height * 1000:F1} mm, products {xy}/{xz}: {full.SpinRpm:F0} rpm (diagonal {diagonal:F0}), spin axis {full.SpinAxisDegrees:F2} deg"));
                        largest = Math.Max(largest, Math.Abs(full.SpinRpm - diagonal) / diagonal);
                        largestRpm = Math.Max(largestRpm, Math.Abs(full.SpinRpm - diagonal));
                        largestTilt = Math.Max(largestTilt, Math.Abs(full.SpinAxisDegrees));
                    }
                }
            }

            TestContext.Out.WriteLine($"largest change {largest:P2} ({largestRpm:F1} rpm), largest spin-axis tilt {largestTilt:F2} deg");
            Assert.That(largest, Is.LessThan(0.005));
            // The numbers docs/impacts.md prints (14 rpm, 0.43 %, 0.31 deg), to their rounding.
            Assert.That(largestRpm, Is.EqualTo(14).Within(0.5));
            Assert.That(largest, Is.EqualTo(0.0043).Within(0.00005));
            Assert.That(largestTilt, Is.EqualTo(0.31).Within(0.005));
        }

        /// <summary>The measured head with its full inertia tensor (g cm^2, table axes: normal, up the face, heel-toe), at 113.2 mph and the loft for 10.8 deg.</summary>
        private static SwingLaunch DriverWithTensorAtThePublishedLaunch(double height, double productNormalUp, double productNormalHeelToe)
        {
            var tensor = new[,] { { 2843, productNormalUp, productNormalHeelToe }, { productNormalUp, 5679, 0.5 }, { productNormalHeelToe, 0.5, 4085 } };
            if (productNormalUp == 0 && productNormalHeelToe == 0)
            {
                tensor[1, 2] = tensor[2, 1] = 0;
            }

            SymmetricEigen(tensor, out double[] moments, out double[,] axes);
            SwingLaunch Hit(double loft)
            {
                var club = new ClubSwing(113.2 * Mph, loft, -1.3, 0, 0, ClubHead.MeasuredDriver);
                Vector3d n = club.FaceNormal(ZUp);
                Vector3d up = SwingGeometry.UpAcross(ZUp, n);
                Vector3d heelToe = Vector3d.Cross(n, up);
                Vector3d Axis(int k) => n * axes[0, k] + up * axes[1, k] + heelToe * axes[2, k];
                var inertia = new RigidBodyInertia(0.204, n * 0.0423 + up * height, Axis(0), Axis(1), moments[0] * 1e-7, moments[1] * 1e-7, moments[2] * 1e-7);
                var body = ImpactBody.Moving(club.PathDirection(ZUp) * club.Speed, n, 0.204);
                return new SwingLaunch(Impact.Resolve(Golf, Vector3d.Zero, Vector3d.Zero, Vector3d.Zero, body, inertia,
                    new ContactProperties(club.Restitution, club.Friction)), ZUp);
            }

            double lo = -5, hi = 60;
            for (int i = 0; i < 60 && hi - lo > 1e-10; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (Hit(mid).ElevationDegrees < 10.8)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            return Hit(0.5 * (lo + hi));
        }

        /// <summary>Cyclic Jacobi rotations of a symmetric 3 x 3 matrix: eigenvalues and eigenvectors (columns of <paramref name="vectors"/>); at most 50 sweeps.</summary>
        private static void SymmetricEigen(double[,] matrix, out double[] values, out double[,] vectors)
        {
            var a = (double[,])matrix.Clone();
            var v = new double[,] { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            for (int sweep = 0; sweep < 50; sweep++)
            {
                for (int p = 0; p < 2; p++)
                {
                    for (int q = p + 1; q < 3; q++)
                    {
                        if (a[p, q] == 0)
                        {
                            continue;
                        }

                        double theta = (a[q, q] - a[p, p]) / (2 * a[p, q]);
                        double t = (theta >= 0 ? 1 : -1) / (Math.Abs(theta) + Math.Sqrt(theta * theta + 1));
                        double c = 1 / Math.Sqrt(t * t + 1), s = t * c;
                        for (int k = 0; k < 3; k++)
                        {
                            double kp = a[k, p], kq = a[k, q];
                            a[k, p] = c * kp - s * kq;
                            a[k, q] = s * kp + c * kq;
                        }

                        for (int k = 0; k < 3; k++)
                        {
                            double pk = a[p, k], qk = a[q, k];
                            a[p, k] = c * pk - s * qk;
                            a[q, k] = s * pk + c * qk;
                        }

                        for (int k = 0; k < 3; k++)
                        {
                            double kp = v[k, p], kq = v[k, q];
                            v[k, p] = c * kp - s * kq;
                            v[k, q] = s * kp + c * kq;
                        }
                    }
                }
            }

            values = new[] { a[0, 0], a[1, 1], a[2, 2] };
            vectors = v;
        }

        [Test]
        public void Driver_TourSpin_WithCrossForceOffset_IsAFit_NotAMeasurement()
        {
            // The Waterloo/Ping paper cut its rigid-body model's backspin errors by moving the ball's centre about 0.5 mm down
            // relative to the impact: the normal force then passes off the ball's centre, as Cross's offset D does. With the
            // point-mass head (the rotating-head law does not take D), at the published launch: D = 0.5 mm gives 3544 rpm,
            // and 2599 rpm needs D = 1.93 mm. Reported, not used: the paper's 0.5 mm was fitted to its own shots.
            SwingLaunch WithOffset(double offset, double loft)
            {
                var club = new ClubSwing(113.2 * Mph, loft, -1.3);
                var body = ImpactBody.Moving(club.PathDirection(ZUp) * club.Speed, club.FaceNormal(ZUp), ClubSwing.DriverHeadMass);
                return new SwingLaunch(Impact.Resolve(Golf, Vector3d.Zero, Vector3d.Zero, Vector3d.Zero, body,
                    new ContactProperties(ClubSwing.UsgaLimitRestitution, 0.4, 0, offset)), ZUp);
            }

            SwingLaunch AtTheLaunch(double offset)
            {
                double lo = -5, hi = 60;
                for (int i = 0; i < 60 && hi - lo > 1e-10; i++)
                {
                    double mid = 0.5 * (lo + hi);
                    if (WithOffset(offset, mid).ElevationDegrees < 10.8)
                    {
                        lo = mid;
                    }
                    else
                    {
                        hi = mid;
                    }
                }

                return WithOffset(offset, 0.5 * (lo + hi));
            }

            SwingLaunch half = AtTheLaunch(0.0005);
            Assert.That(half.SpinRpm, Is.EqualTo(3544).Within(1)); // the number docs/impacts.md prints
            double dLo = 0, dHi = 0.005;
            for (int i = 0; i < 40; i++)
            {
                double mid = 0.5 * (dLo + dHi);
                if (AtTheLaunch(mid).SpinRpm > 2599)
                {
                    dLo = mid;
                }
                else
                {
                    dHi = mid;
                }
            }

            TestContext.Out.WriteLine($"D 0.5 mm: {half.SpinRpm:F0} rpm, {half.Speed / Mph:F2} mph; 2599 rpm needs D = {dLo * 1000:F2} mm");
            Assert.That(dLo, Is.EqualTo(0.00193).Within(0.000005)); // the number docs/impacts.md prints, to its rounding
        }

        [TestCase(RacketSwing.CentreRestitution, 0.911, 0.784)]
        [TestCase(RacketSwing.TipRestitution, 0.805, 0.595)]
        [TestCase(RacketSwing.ThroatRestitution, 0.924, 0.811)]
        public void HandHeldRacket_SpinLoss_DependsOnTheRegime_AndTheImpactPoint(double acor, double gripRatio, double slideRatio)
        {
            // Which case the model is: a hand-held racket is a free body (M = m (1 + ACOR)/(e - ACOR) at the impact point,
            // the same along the face), a clamped one is immovable. A ball thrown at a racket at rest (as in the
            // laboratory): gripping impacts (20-40 deg from the normal) lose spin by the closed form
            // 1 - (1 + alpha)/(1 + alpha (1 + m/M)); sliding ones (70-80 deg) by the share of the normal impulse the
            // free racket takes, 1 - 1/(1 + m/M). The ratios are printed to 3 digits in docs/impacts.md.
            double kappa = Ball.Tennis.Mass / new RacketSwing(1, 0, 0, acor).EffectiveMass(Ball.Tennis);
            double alpha = Ball.Tennis.InertiaFactor;
            foreach ((double angle, bool grips) in new[] { (20.0, true), (40.0, true), (70.0, false), (80.0, false) })
            {
                double a = angle * Math.PI / 180;
                var v = new Vector3d(-20 * Math.Cos(a), 0, -20 * Math.Sin(a));
                SwingLaunch held = new RacketSwing(1e-9, 0, 0, acor).Hit(Ball.Tennis, ZUp, Vector3d.Zero, v, Vector3d.Zero);
                SwingLaunch clamped = new RacketSwing(1e-9, 0, 0, acor, clamped: true).Hit(Ball.Tennis, ZUp, Vector3d.Zero, v, Vector3d.Zero);
                BounceRegime regime = grips ? BounceRegime.Grip : BounceRegime.Slide;
                Assert.That(held.Impact.Regime, Is.EqualTo(regime), $"{angle} deg");
                Assert.That(clamped.Impact.Regime, Is.EqualTo(regime), $"{angle} deg");
                double ratio = held.SpinRate / clamped.SpinRate;
                double expected = grips ? (1 + alpha) / (1 + alpha * (1 + kappa)) : 1 / (1 + kappa);
                // The closed forms, to rounding (the racket's 1e-9 m/s speed enters at 1e-10 of the ball's 20 m/s).
                Assert.That(ratio, Is.EqualTo(expected).Within(1e-8), $"{angle} deg");
                Assert.That(ratio, Is.EqualTo(grips ? gripRatio : slideRatio).Within(5e-4), $"{angle} deg: the ratio docs/impacts.md prints");
            }
        }

        // Lindsey, "String Movement and Spin" (Tennis Warehouse University; no date on the page as read), table "Experimental
        // Spin Results": a racket clamped in a holding device, balls at 56 mph and 40 degrees with -3820 rpm (backspin), 7
        // strings at 52 and 62 lb: 1207 rpm (Wilson NXT 16, 52 lb) to 1803 rpm (Luxilon ALU Rough 16, 52 lb) out. That it is
        // the rig of Cross & Lindsey's "Which Strings Generate the Most Spin?" (same site and co-author, 30 January 2011) is
        // an inference, not stated: the same 40 deg, but 56 mph against that abstract's "around 23 m/s (51 mph)". The page
        // words the angle "40 degrees to the stringbed"; the 40 deg is taken from the normal, as that abstract words it
        // ("40 deg away from the normal") and as Lindsey's twistweight page measures its 24 deg ("to the racquet face
        // perpendicular"), not because it passes (the other reading is printed below).
        private const double LindseySpeed = 56 * Mph;
        private const double LindseyAngleDegrees = 40;
        private const double LindseySpinInRpm = -3820;

        // A ball at `speed` m/s, `angleDegrees` from the face normal (+x, a racket at rest with tilt 0), spinning `spinRpm`
        // about the axis it would roll about on the strings (positive: the way it leaves a gripping impact; negative:
        // backspin, which adds to the contact point's slip along the face and which the strings must reverse, as the
        // table's -3820 rpm in and 1207-1803 rpm out). Returns the spin out about the same axis, rpm, and the regime.
        private static double SpinOutRpm(double speed, double angleDegrees, double spinRpm, double acor, bool clamped, out BounceRegime regime)
        {
            double a = angleDegrees * Math.PI / 180;
            Vector3d normal = Vector3d.UnitX;
            var velocity = new Vector3d(-speed * Math.Cos(a), 0, -speed * Math.Sin(a));
            // A ball sliding along -z on a face with normal +x rolls about n x t = x x (-z) = +y.
            Vector3d rollAxis = Vector3d.Cross(normal, -Vector3d.UnitZ);
            Vector3d spin = rollAxis * (spinRpm * 2 * Math.PI / 60);
            SwingLaunch l = new RacketSwing(1e-9, 0, 0, acor, clamped: clamped).Hit(Ball.Tennis, ZUp, Vector3d.Zero, velocity, spin);
            regime = l.Impact.Regime;
            return Vector3d.Dot(l.Impact.AngularVelocity, rollAxis) * 60 / (2 * Math.PI);
        }

        [Test]
        public void ClampedRacket_SpinOut_IsInsideTheMeasuredRangeOfFourteenStringBeds()
        {
            // Lindsey's table (above): 1207-1803 rpm over 14 string beds. The model has one string bed (e 0.85, mu 0.4, no
            // snap-back), so the check is that it lands inside the strings' measured spread, not on one of them.
            double rpm = SpinOutRpm(LindseySpeed, LindseyAngleDegrees, LindseySpinInRpm, RacketSwing.CentreRestitution, clamped: true, out BounceRegime regime);
            TestContext.Out.WriteLine($"clamped, 56 mph at 40 deg with -3820 rpm: {rpm:F0} rpm out ({regime}); measured 1207-1803 rpm");
            Assert.That(regime, Is.EqualTo(BounceRegime.Grip), "mu 0.4 grips at 40 deg even with the incoming backspin");
            Assert.That(rpm, Is.InRange(1207.0, 1803.0));
            // Printed in docs/impacts.md (to the rpm).
            Assert.That(rpm, Is.EqualTo(1649).Within(0.5));

            // The other reading of "40 degrees to the stringbed" (50 deg from the normal), printed in docs/impacts.md to
            // show what the choice of reading is worth; it is not the reading checked above.
            double otherReading = SpinOutRpm(LindseySpeed, 90 - LindseyAngleDegrees, LindseySpinInRpm, RacketSwing.CentreRestitution, clamped: true, out BounceRegime otherRegime);
            TestContext.Out.WriteLine($"clamped, 56 mph at 50 deg from the normal with -3820 rpm: {otherReading:F0} rpm out ({otherRegime})");
            Assert.That(otherReading, Is.EqualTo(2225).Within(0.5), "printed in docs/impacts.md");
        }

        [TestCase(LindseySpeed, 29.6)]
        [TestCase(23.0, 33.2)]
        public void HandHeldRacket_WithIncomingBackspin_GivesAbout30PercentLessSpin(double speed, double printedLossPercent)
        {
            // Cross & Lindsey, "The Physics of Tennis: Which Strings Generate the Most Spin?" (Tennis Warehouse University,
            // 30 January 2011), abstract: balls incident with backspin at around 23 m/s, 40 deg from the normal, 16 strings,
            // clamped and hand-held racquets: "the outgoing ball spin decreases by about 30 % when the racquet is hand-held".
            // The abstract gives no incoming spin; Lindsey's clamped-racket table (above) uses -3820 rpm at 56 mph, so both
            // speeds are flown with it (an assumption: the loss depends strongly on it, printed below). The impact point is
            // taken as the string centre (ACOR 0.45; not stated in what was read).
            double clamped = SpinOutRpm(speed, LindseyAngleDegrees, LindseySpinInRpm, RacketSwing.CentreRestitution, clamped: true, out BounceRegime clampedRegime);
            double held = SpinOutRpm(speed, LindseyAngleDegrees, LindseySpinInRpm, RacketSwing.CentreRestitution, clamped: false, out BounceRegime heldRegime);
            double loss = 100 * (1 - held / clamped);
            TestContext.Out.WriteLine($"{speed:F2} m/s: clamped {clamped:F0} rpm ({clampedRegime}), hand-held {held:F0} rpm ({heldRegime}): {loss:F1} % less");
            Assert.That(clampedRegime, Is.EqualTo(BounceRegime.Grip));
            Assert.That(heldRegime, Is.EqualTo(BounceRegime.Grip));
            // "About 30 %", a round number: read as 30 % to the nearest ten, +-5 points.
            Assert.That(loss, Is.InRange(25.0, 35.0));
            Assert.That(loss, Is.EqualTo(printedLossPercent).Within(0.05), "the loss docs/impacts.md prints");

            // Why the backspin matters: a gripping ball leaves rolling with R w_out = (v_t + alpha' R w_in)/(1 + alpha'), where
            // v_t is its speed along the face, w_in its spin about the rolling axis and alpha' = alpha (1 + m/M) (docs/impacts.md,
            // the law): alpha for the clamped racket, 27.6 % more for the free one at the centre (m/M = 0.4/1.45 = 0.276). Backspin (w_in < 0)
            // cancels much of v_t, and it cancels more with the larger alpha', so the share lost grows from the 8.9 % of a ball
            // arriving without spin (HandHeldRacket_SpinLoss_DependsOnTheRegime_AndTheImpactPoint) to about 30 %.
            double alpha = Ball.Tennis.InertiaFactor;
            double alphaHeld = alpha * (1 + Ball.Tennis.Mass / new RacketSwing(1, 0, 0).EffectiveMass(Ball.Tennis));
            double vt = speed * Math.Sin(LindseyAngleDegrees * Math.PI / 180);
            double rw = Ball.Tennis.Radius * LindseySpinInRpm * 2 * Math.PI / 60;
            double expected = (vt + alphaHeld * rw) / (1 + alphaHeld) / ((vt + alpha * rw) / (1 + alpha));
            Assert.That(held / clamped, Is.EqualTo(expected).Within(1e-8), "the closed form (the racket's 1e-9 m/s enters at 1e-10)");
            double clampedNoSpin = SpinOutRpm(speed, LindseyAngleDegrees, 0, RacketSwing.CentreRestitution, clamped: true, out _);
            double heldNoSpin = SpinOutRpm(speed, LindseyAngleDegrees, 0, RacketSwing.CentreRestitution, clamped: false, out _);
            Assert.That(100 * (1 - heldNoSpin / clampedNoSpin), Is.EqualTo(8.9).Within(0.05), "without incoming spin");

            // How much the check rests on the assumed incoming spin (printed in docs/impacts.md): the loss grows with the
            // backspin, from the 8.9 % above, through the -3820 rpm case.
            double previous = 100 * (1 - heldNoSpin / clampedNoSpin);
            foreach (double spinIn in new[] { -3000.0, -3500, LindseySpinInRpm, -4000, -4500 })
            {
                double c = SpinOutRpm(speed, LindseyAngleDegrees, spinIn, RacketSwing.CentreRestitution, clamped: true, out BounceRegime cr);
                double h = SpinOutRpm(speed, LindseyAngleDegrees, spinIn, RacketSwing.CentreRestitution, clamped: false, out BounceRegime hr);
                double l = 100 * (1 - h / c);
                TestContext.Out.WriteLine($"{speed:F2} m/s, {spinIn:F0} rpm in: clamped {c:F0} rpm ({cr}), hand-held {h:F0} rpm ({hr}): {l:F1} % less");
                Assert.That(l, Is.GreaterThan(previous), "more incoming backspin, a larger share lost");
                previous = l;
            }
        }

        private static SwingLaunch HitWithRecoil(double speed, double loft, double attack, double headMass, double e, double tangentialRestitution)
        {
            // ClubSwing's impact with Cross's grip recoil e_x added (the helper itself has e_x = 0).
            var club = new ClubSwing(speed, loft, attack, headMass: headMass, restitution: e);
            var body = ImpactBody.Moving(club.PathDirection(ZUp) * speed, club.FaceNormal(ZUp), headMass);
            var contact = new ContactProperties(e, club.Friction, tangentialRestitution);
            return new SwingLaunch(Impact.Resolve(Golf, Vector3d.Zero, Vector3d.Zero, Vector3d.Zero, body, contact), ZUp);
        }

        private static double LoftForLaunch(double speed, double attack, double headMass, double e, double launchDegrees, double tangentialRestitution = 0)
        {
            // The launch angle rises with the loft: bisection to 1e-10 deg (at most 40 halvings of 65 deg).
            double lo = -5, hi = 60;
            for (int i = 0; i < 60 && hi - lo > 1e-10; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (HitWithRecoil(speed, mid, attack, headMass, e, tangentialRestitution).ElevationDegrees < launchDegrees)
                {
                    lo = mid;
                }
                else
                {
                    hi = mid;
                }
            }

            return 0.5 * (lo + hi);
        }
    }
}
