using System;
using MagnusBall.Integration;
using MagnusBall.Presets;
using NUnit.Framework;

namespace MagnusBall.Tests.Presets
{
    /// <summary>
    /// Each preset flies its sport's characteristic shot to a documented outcome. Frames vary on purpose
    /// (z-up and y-up) since nothing may assume an axis is up.
    /// </summary>
    [TestFixture]
    public class CharacteristicShotTests
    {
        private static readonly Vector3d ZUp = Vector3d.UnitZ;
        private static readonly Vector3d Downrange = Vector3d.UnitX;

        private static ShotOutcome GolfShot(SportPreset preset, Air air, double mph, double elevation, double rpm) =>
            ShotFlight.Fly(
                preset.CreateModel(air, Gravity.ZUp),
                ShotFlight.Launch(ZUp, Downrange, 0, mph * ShotFlight.MetresPerSecondPerMph, elevation, v => Spin.Backspin(v, ZUp, Spin.FromRpm(rpm))));

        [Test]
        public void GolfLinear2023_KeepsItsTwoCalibratedCarries()
        {
            // TrackMan 2023 tour averages (data/published/trackman-tour-averages.json). The golf preset before
            // issue 12, kept as golf-linear-2023: its two drag constants were calibrated to these two carries
            // (282 yd, 176 yd), so the carries check that calibration; apex and landing angle are predictions.
            // The golf preset itself is checked against all tour averages in Validation/GolfValidationTests.
            ShotOutcome driver = GolfShot(SportPresets.GolfLinear2023, Air.SeaLevel, 171, 10.4, 2545);
            ShotOutcome iron = GolfShot(SportPresets.GolfLinear2023, Air.SeaLevel, 123, 16.1, 7124);
            double driverCarry = driver.Landing.X / ShotFlight.MetresPerYard;
            double ironCarry = iron.Landing.X / ShotFlight.MetresPerYard;
            double ironApex = iron.Apex / ShotFlight.MetresPerYard;
            double ironAngle = ShotFlight.LandingAngleDegrees(iron, ZUp);
            TestContext.Out.WriteLine(
                $"driver carry {driverCarry:F1} yd, apex {driver.Apex / ShotFlight.MetresPerYard:F1} yd, landing {ShotFlight.LandingAngleDegrees(driver, ZUp):F1} deg; " +
                $"7-iron carry {ironCarry:F1} yd, apex {ironApex:F1} yd, landing {ironAngle:F1} deg");

            // 1 yd: the calibrated constants are rounded to 4 decimals (worth about 0.5 yd), TrackMan to 1 yd.
            Assert.That(driverCarry, Is.EqualTo(282).Within(1));
            Assert.That(ironCarry, Is.EqualTo(176).Within(1));
            // Not calibrated: 10 % of the apex and 5 deg of landing angle are the "believable to a golfer"
            // bounds set for this preset (a few yards of height, a few degrees of descent).
            Assert.That(ironApex, Is.EqualTo(34).Within(10).Percent);
            Assert.That(ironAngle, Is.EqualTo(51).Within(5));
            Assert.That(ShotFlight.LandingAngleDegrees(driver, ZUp), Is.LessThan(ironAngle));
        }

        [Test]
        public void Golf_PublishedSmitsSmithDrag_CarriesTheDriverShortAndTheIronLong()
        {
            // Documents why the preset is calibrated: the uncalibrated law misses both carries in opposite directions.
            double driver = GolfShot(SportPresets.GolfSmitsSmith, Air.SeaLevel, 171, 10.4, 2545).Landing.X / ShotFlight.MetresPerYard;
            double iron = GolfShot(SportPresets.GolfSmitsSmith, Air.SeaLevel, 123, 16.1, 7124).Landing.X / ShotFlight.MetresPerYard;
            TestContext.Out.WriteLine($"Smits & Smith as published: driver {driver:F1} yd, 7-iron {iron:F1} yd");
            Assert.That(driver, Is.LessThan(282 - 15));
            Assert.That(iron, Is.GreaterThan(176));
        }

        [Test]
        public void Golf_ThinWarmAirAndACrosswind_CarryFartherAndDrift()
        {
            // The example: 25 degC, 1600 m, 3 m/s crosswind (from -y, blowing +y). Thinner air means
            // less drag and less lift; for a driver the drag wins (golfers' "ball flies farther at altitude").
            ShotOutcome seaLevel = GolfShot(SportPresets.Golf, Air.SeaLevel, 171, 10.4, 2545);
            Air mountain = Air.AtAltitude(1600, 25, 0, new Vector3d(0, 3, 0));
            ShotOutcome high = GolfShot(SportPresets.Golf, mountain, 171, 10.4, 2545);
            ShotOutcome iron = GolfShot(SportPresets.Golf, Air.SeaLevel, 123, 16.1, 7124);
            // For docs/presets.md (the golf preset's sample flights): the 2023 tour driver and 7-iron in ISA sea-level air.
            TestContext.Out.WriteLine(
                $"golf, ISA sea level: driver carry {seaLevel.Landing.X / ShotFlight.MetresPerYard:F1} yd, apex {seaLevel.Apex / ShotFlight.MetresPerYard:F1} yd, landing {ShotFlight.LandingAngleDegrees(seaLevel, Vector3d.UnitZ):F1} deg; " +
                $"7-iron carry {iron.Landing.X / ShotFlight.MetresPerYard:F1} yd, apex {iron.Apex / ShotFlight.MetresPerYard:F1} yd, landing {ShotFlight.LandingAngleDegrees(iron, Vector3d.UnitZ):F1} deg");
            TestContext.Out.WriteLine($"driver at 1600 m, 25 degC, 3 m/s crosswind: carry {high.Landing.X / ShotFlight.MetresPerYard:F1} yd, drift {high.Landing.Y:F1} m");
            Assert.That(high.Landing.X, Is.GreaterThan(seaLevel.Landing.X));
            Assert.That(high.Landing.Y, Is.GreaterThan(0));

            // With the wind measured at 10 m over fairway grass (z0 = 0.03 m) the log profile blows less
            // near the ground (apex ~30 m is above 10 m, so part of the flight sees more): the drift differs
            // from the uniform wind's but keeps its direction.
            Air profiled = Air.AtAltitude(1600, 25).WithLogarithmicWind(new Vector3d(0, 3, 0), 10, 0.03);
            ShotOutcome logWind = GolfShot(SportPresets.Golf, profiled, 171, 10.4, 2545);
            TestContext.Out.WriteLine($"same with a log profile: drift {logWind.Landing.Y:F1} m");
            Assert.That(logWind.Landing.Y, Is.GreaterThan(0));
            Assert.That(logWind.Landing.Y, Is.Not.EqualTo(high.Landing.Y).Within(0.05));
        }

        [Test]
        public void Tennis_CrossDrives_ReachTheBaseline()
        {
            // Cross (2011): from 1.0 m at 30 m/s, rho 1.21, the minimum angles to reach the baseline (23.77 m)
            // are 8.1 deg without spin and 11.9 deg with 20 rev/s topspin.
            var air = new Air(1.21);
            FlightModel model = SportPresets.Tennis.CreateModel(air, Gravity.YUp);
            Vector3d up = Vector3d.UnitY;
            Vector3d downrange = Vector3d.UnitZ;
            ShotOutcome flat = ShotFlight.Fly(model, ShotFlight.Launch(up, downrange, 1.0, 30, 8.1, v => Vector3d.Zero));
            ShotOutcome topspin = ShotFlight.Fly(model, ShotFlight.Launch(up, downrange, 1.0, 30, 11.9,
                v => Spin.Topspin(v, up, Spin.FromRevolutionsPerSecond(20))));
            FlightModel free = SportPresets.TennisFreeFlight.CreateModel(air, Gravity.YUp);
            ShotOutcome freeTopspin = ShotFlight.Fly(free, ShotFlight.Launch(up, downrange, 1.0, 30, 11.9,
                v => Spin.Topspin(v, up, Spin.FromRevolutionsPerSecond(20))));
            TestContext.Out.WriteLine($"tennis: flat 8.1 deg lands at {flat.Landing.Z:F2} m, 20 rev/s topspin 11.9 deg at {topspin.Landing.Z:F2} m; " +
                                      $"tennis-free-flight, the topspin drive: {freeTopspin.Landing.Z:F2} m");
            // 0.5 m: Cross's angles are read from the book's chart to 0.1 deg (0.1 deg moves these landings by
            // about 0.2 m). The preset flies Cross's own ball (Ball.Tennis, 57 g, 33 mm) with Stepanek's laws and spin
            // decay, where Cross's chart is his own model's.
            Assert.That(flat.Landing.Z, Is.EqualTo(23.77).Within(0.5));
            Assert.That(topspin.Landing.Z, Is.EqualTo(23.77).Within(0.5));
            // The free-flight preset's constant C_D 0.507 is below Stepanek's spin-raised drag (0.58 at the launch, S = 0.14), and its
            // lift is the same law: the same drive flies farther.
            Assert.That(freeTopspin.Landing.Z, Is.GreaterThan(topspin.Landing.Z));
        }

        [Test]
        public void Soccer_JavorovaFreeKick_CurvesAboutThreeMetres()
        {
            // Javorova & Ivanov (2018), as quoted by the seed thesis: 24.15 m/s, 61.86 rad/s of sidespin, from 20 m,
            // reaches the goal line 3.2 m to the side and 2.2 m high. The launch elevation was not published:
            // it is solved here so the ball crosses the goal line 2.2 m high, kicked straight at the goal.
            FlightModel model = SportPresets.Soccer.CreateModel(Air.SeaLevel, Gravity.ZUp);
            Vector3d side = Vector3d.UnitY;
            double low = 5, high = 30;
            Vector3d atGoalLine = default;
            for (int i = 0; i < 40; i++)
            {
                double elevation = 0.5 * (low + high);
                FlightState start = ShotFlight.Launch(ZUp, Downrange, 0.11, 24.15, elevation, v => Spin.Toward(v, side, 61.86));
                atGoalLine = CrossingOfPlane(model, start, Downrange, 20);
                if (atGoalLine.Z < 2.2) { low = elevation; } else { high = elevation; }
            }

            TestContext.Out.WriteLine($"soccer: elevation {low:F2} deg, at the goal line {atGoalLine.Y:F2} m to the side, {atGoalLine.Z:F2} m high");
            // 0.5 m: the kick direction and the coefficients were not published (the thesis's own model got
            // 3.3 m); half a metre is the size of the thesis-to-paper gap plus the unknown kick direction.
            Assert.That(atGoalLine.Y, Is.EqualTo(3.2).Within(0.5));
        }

        [Test]
        public void Baseball_FlyBall_CarriesAbout400Feet()
        {
            // Nathan's calculator-era rule of thumb (docs/references.md section 6) is stated for a 400 ft fly
            // ball; a 100 mph, 28 deg, 1800 rpm drive is a typical Statcast home-run launch. 30 ft: the spread of
            // carries for such launches in Statcast data is tens of feet; this checks the preset is in the league.
            Air air = Air.FromWeather(21.1, 101325); // 70 degF, standard pressure, dry
            double carry = BaseballRulesOfThumbTests.CarryFeet(air, 100);
            TestContext.Out.WriteLine($"baseball 100 mph, 28 deg, 1800 rpm: {carry:F1} ft");
            Assert.That(carry, Is.EqualTo(400).Within(30));
        }

        [Test]
        public void TableTennis_TopspinDrive_Dips_TheFlatOneGoesLong()
        {
            // ITTF table: 2.74 m long, net 1.37 m from each end. Shot: 15 m/s at 5 deg from 0.3 m above the
            // table over the server's end line; 100 rev/s (6000 rpm) of topspin, a strong loop. The documented
            // outcome is the reason players use topspin: the spinning drive lands on the far half of the table,
            // the same drive without spin goes long.
            FlightModel model = SportPresets.TableTennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
            ShotOutcome loop = ShotFlight.Fly(model, ShotFlight.Launch(ZUp, Downrange, 0.3, 15, 5,
                v => Spin.Topspin(v, ZUp, Spin.FromRevolutionsPerSecond(100))));
            ShotOutcome flat = ShotFlight.Fly(model, ShotFlight.Launch(ZUp, Downrange, 0.3, 15, 5, v => Vector3d.Zero));
            TestContext.Out.WriteLine($"table tennis: loop lands at {loop.Landing.X:F2} m, flat drive at {flat.Landing.X:F2} m");
            // With the preset's table-tennis coefficients (Conti et al. 2026: at this shot's S 0.84 C_L is about 0.22 and
            // C_D about 0.43) this loop lands about 0.18 m past the end line; with the tennis lift borrowed before issue 43
            // (C_L 0.31 there) it landed on the table. The shot is not a measured one, so it is not tuned: the checks are
            // that topspin pulls the drive down by more than half the table's length, past the net, and that the flat
            // drive goes long.
            Assert.That(loop.Landing.X, Is.LessThan(flat.Landing.X - 1.37));
            Assert.That(loop.Landing.X, Is.GreaterThan(1.37));
            Assert.That(flat.Landing.X, Is.GreaterThan(2.74));
        }

        [Test]
        public void TableTennis_DroppedBall_ReachesItsTerminalSpeed()
        {
            // Closed form: v_t = sqrt(2 m g / (rho A C_D(v_t))) for 2.7 g, 40 mm at 1.225 kg/m^3, with the preset's
            // speed-dependent C_D without spin (Conti et al. 2026's table) solved by fixed-point iteration: about 8.4 m/s.
            FlightModel model = SportPresets.TableTennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
            ShotOutcome drop = ShotFlight.Fly(model, new FlightState(new Vector3d(0, 0, 30), Vector3d.Zero, Vector3d.Zero));
            double terminal = 8;
            for (int i = 0; i < 100; i++)
            {
                terminal = Math.Sqrt(2 * 0.0027 * Gravity.Standard / (1.225 * Math.PI * 0.02 * 0.02 * MagnusBall.Aerodynamics.ContiTableTennisDrag.Evaluate(terminal, 0)));
            }

            // 0.5 %: from rest v = v_t tanh(g t / v_t); the 30 m drop takes about 4.1 s, g t / v_t = 4.7, so the
            // ball is within 1 - tanh(4.7) = 1.6e-4 of v_t; 0.5 % leaves room for nothing else to be wrong.
            Assert.That(drop.LandingVelocity.Length, Is.EqualTo(terminal).Within(0.5).Percent);
        }

        [Test]
        public void Basketball_FreeThrow_NeedsAboutSevenMetresPerSecond()
        {
            // Tran & Silverberg (2008, Sports Engineering 10:1) recommend a 52 deg release with 3 Hz of backspin.
            // Geometry (FIBA/NBA): rim 3.05 m high, its centre 4.19 m in front of the free-throw line; release
            // assumed 2.13 m high (7 ft) at the line. Solve the release speed that drops the centre through the
            // rim centre's height at 4.19 m.
            FlightModel model = SportPresets.Basketball.CreateModel(Air.SeaLevel, Gravity.ZUp);
            FlightModel vacuum = FlightModel.Vacuum(SportPresets.Basketball.Ball, Gravity.ZUp);
            double withAir = FreeThrowSpeed(model);
            double inVacuum = FreeThrowSpeed(vacuum);
            TestContext.Out.WriteLine($"basketball free throw: {withAir:F3} m/s with air, {inVacuum:F3} m/s in vacuum");
            // Drag costs speed; 7.0-7.6 m/s brackets the release speeds reported for free throws (about 7 m/s).
            Assert.That(withAir, Is.GreaterThan(inVacuum));
            Assert.That(withAir, Is.InRange(7.0, 7.6));
        }

        private static double FreeThrowSpeed(FlightModel model)
        {
            double low = 5, high = 10;
            for (int i = 0; i < 40; i++)
            {
                double speed = 0.5 * (low + high);
                FlightState state = ShotFlight.Launch(ZUp, Downrange, 2.13, speed, 52, v => Spin.Backspin(v, ZUp, Spin.FromRevolutionsPerSecond(3)));
                double x = DescendingCrossingOfHeight(model, state, 3.05);
                if (x < 4.19) { low = speed; } else { high = speed; }
            }

            return 0.5 * (low + high);
        }

        /// <summary>Where (along x) the centre comes down through <paramref name="height"/>, linear in the last 1 ms step.</summary>
        private static double DescendingCrossingOfHeight(FlightModel model, FlightState state, double height)
        {
            StateDerivative d = model.Derivative(state);
            while (state.Time < 10)
            {
                FlightState next = ((IIntegrator)RungeKutta4.Instance).Step(model, state, d, ShotFlight.Step);
                if (next.Velocity.Z < 0 && state.Position.Z >= height && next.Position.Z < height)
                {
                    double t = (state.Position.Z - height) / (state.Position.Z - next.Position.Z);
                    return state.Position.X + t * (next.Position.X - state.Position.X);
                }

                state = next;
                d = model.Derivative(state);
            }

            throw new InvalidOperationException("the ball never came down through the height");
        }

        /// <summary>Where the centre crosses the plane normal . p = distance, linear in the last 1 ms step.</summary>
        private static Vector3d CrossingOfPlane(FlightModel model, FlightState state, Vector3d normal, double distance)
        {
            StateDerivative d = model.Derivative(state);
            while (state.Time < 10)
            {
                FlightState next = ((IIntegrator)RungeKutta4.Instance).Step(model, state, d, ShotFlight.Step);
                double a = Vector3d.Dot(state.Position, normal) - distance;
                double b = Vector3d.Dot(next.Position, normal) - distance;
                if (a < 0 && b >= 0)
                {
                    return Vector3d.Lerp(state.Position, next.Position, -a / (b - a));
                }

                state = next;
                d = model.Derivative(state);
            }

            throw new InvalidOperationException("the ball never reached the plane");
        }
    }
}
