using System;
using System.Text.Json;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Shots;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// The restitutions of <see cref="SportShapes"/> against the published contact measurements found with their numbers
    /// (data/published/ball-rebound-rules.json): the governing bodies' ball-rebound tests (FIBA, FIFA, ITF: a ball dropped
    /// square onto a hard surface) and the NCAA/FIBA basket-ring test (the share of a drop's energy the ring absorbs). Each
    /// test drops the sport's ball (its preset, with air) as the rule does, flies it through a <see cref="FlightStepper"/>
    /// onto the sport's fixture as <see cref="SportShapes"/> builds it (answered by Contact.Impact with the fixture's
    /// restitution) and compares the rebound with the rule's band. The band is the tolerance: it is the spread the rule
    /// allows between conforming balls (or rings). The assumption, stated once: a rigid fixture (a glass backboard, a metal
    /// post or bar) meets the ball as the rule's floor, plate or block does, so the ball's own losses set the restitution.
    /// <see cref="SportShapes.Board"/> and <see cref="SportShapes.Post"/> are taken from these bands, so for them the tests
    /// hold the value where the sources put it; <see cref="SportShapes.Rim"/> (0.6, a game value) is an independent check.
    /// Here, not in Contact/, because it reads JSON (left out of the Mono build).
    /// </summary>
    [TestFixture]
    [Category("Validation")]
    public class PublishedContactTests
    {
        private const double Step = 1.0 / 2000;

        private static JsonElement Data() => PublishedCases.Load("ball-rebound-rules.json");

        private static JsonElement Case(string sport)
        {
            foreach (JsonElement c in Data().GetProperty("cases").EnumerateArray())
            {
                if (c.GetProperty("sport").GetString() == sport)
                {
                    return c;
                }
            }

            Assert.Fail($"ball-rebound-rules.json has no {sport} case.");
            return default;
        }

        private static FlightModel Model(SportPreset preset) => preset.CreateModel(Air.SeaLevel, Gravity.ZUp);

        /// <summary>
        /// Drops the ball, without spin, with its bottom <paramref name="dropHeight"/> above the top of a horizontal surface
        /// at <paramref name="surfaceTop"/> (z up), and returns the ball centre's highest point above that top after the
        /// bounce, m. Exactly one contact, with shape <paramref name="expectedId"/>, square on.
        /// </summary>
        private static double CentreApexAfterBounce(FlightModel model, ContactShape[] shapes, Vector3d surfaceTop, double dropHeight, int expectedId)
        {
            var stepper = new FlightStepper(model, RungeKutta4.Instance, null, null, shapes);
            stepper.Reset(new FlightState(surfaceTop + new Vector3d(0, 0, dropHeight + model.Ball.Radius), Vector3d.Zero, Vector3d.Zero));
            int contacts = 0;
            double apex = double.NegativeInfinity;
            for (int i = 0; i < 20000 && !stepper.IsStopped; i++)
            {
                stepper.TryStep(Step);
                foreach (FlightEvent e in stepper.Events)
                {
                    if (e.Kind == FlightEventKinds.Contact)
                    {
                        contacts++;
                        Assert.That(e.ShapeId, Is.EqualTo(expectedId), "the drop meets the fixture's surface");
                        Assert.That(e.ContactNormal.Z, Is.GreaterThan(1 - 1e-9), "square on");
                    }
                }

                if (contacts > 0)
                {
                    apex = Math.Max(apex, stepper.State.Position.Z - surfaceTop.Z);
                    if (stepper.State.Velocity.Z < 0)
                    {
                        break;
                    }
                }
            }

            Assert.That(contacts, Is.EqualTo(1), "one bounce, then the apex");
            return apex;
        }

        // The same drop onto a rigid plate of restitution e (a square drop without spin does not use the friction).
        private static double CentreApexOnPlate(FlightModel model, double restitution, double dropHeight)
        {
            var plate = BoxShape.Rectangle(0, Vector3d.Zero, Vector3d.UnitZ, Vector3d.UnitX, 1, 1, new ContactProperties(restitution, 0.3));
            return CentreApexAfterBounce(model, new ContactShape[] { plate }, Vector3d.Zero, dropHeight, 0);
        }

        /// <summary>The restitution whose flown drop reaches <paramref name="centreApex"/>: the rule's edge as a restitution, to 1e-9.</summary>
        private static double RestitutionFor(FlightModel model, double dropHeight, double centreApex)
        {
            double lo = 0.3, hi = 1;
            while (hi - lo > 1e-9)
            {
                double mid = 0.5 * (lo + hi);
                if (CentreApexOnPlate(model, mid, dropHeight) < centreApex)
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

        /// <summary>
        /// The FIBA ball's restitution band on a hard surface: the e whose flown drop (1.80 m to the bottom of the ball)
        /// rebounds to the rule's 1.20 and 1.40 m (to the top of the ball). Uses the basketball preset's drag (C_D 0.54, not
        /// traced to a measurement: docs/presets.md); without air the band would be 0.730-0.802.
        /// </summary>
        private static (double Low, double High) FibaBallRestitution()
        {
            JsonElement c = Case("basketball");
            FlightModel model = Model(SportPresets.Basketball);
            double r = model.Ball.Radius, drop = c.Number("drop_height_m");
            return (RestitutionFor(model, drop, c.Number("rebound_min_m") - r), RestitutionFor(model, drop, c.Number("rebound_max_m") - r));
        }

        [Test]
        public void Basketball_OnTheBackboard_ReboundsWithinFibasBand()
        {
            // FIBA: dropped 1.80 m (to the bottom of the ball) onto the playing surface, it rebounds to 1.20-1.40 m (to the
            // top of the ball). Flown onto SportShapes.BasketballHoop's backboard in place of the floor: the hoop is built
            // turned so that its board faces up (the builder takes any frame; the ring then stands up off the board 0.4 m
            // from where the ball lands).
            JsonElement c = Case("basketball");
            double drop = c.Number("drop_height_m"), min = c.Number("rebound_min_m"), max = c.Number("rebound_max_m");
            FlightModel model = Model(SportPresets.Basketball);
            double r = model.Ball.Radius;
            ContactShape[] hoop = SportShapes.BasketballHoop(0, Vector3d.Zero, Vector3d.UnitZ, Vector3d.UnitX);
            // The board's centre is 2.90 + 1.05 / 2 m along "up" (here x) from the foot, its face the plane z = 0.
            var landing = new Vector3d(SportShapes.BackboardLowerEdgeMetres + SportShapes.BackboardHeightMetres / 2 + 0.33, 0, 0);
            double top = CentreApexAfterBounce(model, hoop, landing, drop, 1) + r;
            (double eLow, double eHigh) = FibaBallRestitution();
            TestContext.Out.WriteLine(
                $"basketball on the backboard (e {SportShapes.Board.NormalRestitution}): rebounds to {top:F3} m (top of the ball); FIBA {min}-{max} m, e {eLow:F3}-{eHigh:F3}");
            Assert.That(top, Is.InRange(min, max));
            Assert.That(SportShapes.Board.NormalRestitution, Is.InRange(eLow, eHigh));
        }

        [Test]
        public void Basketball_OnTheRing_ReboundsWithinTheRingRulesBand()
        {
            // NCAA/FIBA: the ring and its support absorb 35-50 % of a drop's energy (a 5 lb weight dropped 4 ft, the tester
            // calibrated on a solid floor). With the ball's own band on a hard surface (FIBA, above), a ball on the ring keeps
            // 50-65 % of the rebound energy a rigid support would give it: e_ring = e_ball sqrt(1 - absorbed), e_ball from
            // FIBA's band. Assumed: the share a 2.27 kg weight loses carries over to a 0.6 kg ball, and the ring meets the
            // ball square on its top as it meets the weight. SportShapes.Rim's 0.6 is a game value, checked here, not fitted.
            JsonElement ring = Data().GetProperty("ring");
            double absorbedMin = ring.Number("energy_absorbed_min"), absorbedMax = ring.Number("energy_absorbed_max");
            (double eBallLow, double eBallHigh) = FibaBallRestitution();
            double eLow = eBallLow * Math.Sqrt(1 - absorbedMax), eHigh = eBallHigh * Math.Sqrt(1 - absorbedMin);
            foreach (JsonElement measured in ring.GetProperty("measured_examples").EnumerateArray())
            {
                double absorbed = measured.GetProperty("energy_absorbed").GetDouble();
                Assert.That(absorbed, Is.InRange(absorbedMin, absorbedMax), "the measured rims meet the rule");
            }

            // The hoop as it stands: dropped from 1.80 m onto the top of the ring's front (its top is 3.05 m up).
            FlightModel model = Model(SportPresets.Basketball);
            double r = model.Ball.Radius, drop = Case("basketball").Number("drop_height_m");
            ContactShape[] hoop = SportShapes.BasketballHoop(0, Vector3d.Zero, Vector3d.UnitX, Vector3d.UnitZ);
            var rim = (TorusShape)hoop[0];
            var ringTop = new Vector3d(rim.Centre.X + rim.RingRadiusM, 0, rim.Centre.Z + rim.TubeRadiusM);
            double apex = CentreApexAfterBounce(model, hoop, ringTop, drop, 0);
            double low = CentreApexOnPlate(model, eLow, drop), high = CentreApexOnPlate(model, eHigh, drop);
            TestContext.Out.WriteLine(
                $"basketball on the ring (e {SportShapes.Rim.NormalRestitution}): rebounds to {apex - r:F3} m (bottom of the ball, above the ring); " +
                $"the rules' band {low - r:F3}-{high - r:F3} m, e {eLow:F3}-{eHigh:F3}");
            Assert.That(apex, Is.InRange(low, high));
            Assert.That(SportShapes.Rim.NormalRestitution, Is.InRange(eLow, eHigh));
        }

        [Test]
        public void SoccerBall_OnTheCrossbar_FifasBand_MetMeasuredToTheTop_MissedByTheBottom()
        {
            // FIFA Quality: dropped from 2 m onto a steel plate, 115-165 cm. Flown onto the top of SportShapes.SoccerGoalFrame's
            // crossbar (0.12 m), a metal bar met square on. The source does not say which point of the ball the rebound is
            // measured to. Read to the top of the ball, the bar's restitution (0.765) is inside the band (e 0.709-0.886); read
            // to the bottom it is under it (e from 0.791), 7 cm short: SportShapes.Post is shared with the tennis net's posts,
            // and the ITF's band (TennisBall_OnTheNetPost_*) caps it at 0.771 read to the top, 0.790 to the bottom, under FIFA's
            // 0.791 read to the bottom. The miss is recorded, not widened.
            JsonElement c = Case("soccer");
            double drop = c.Number("drop_height_m"), min = c.Number("rebound_min_m"), max = c.Number("rebound_max_m");
            FlightModel model = Model(SportPresets.Soccer);
            double r = model.Ball.Radius;
            ContactShape[] frame = SportShapes.SoccerGoalFrame(0, Vector3d.Zero, Vector3d.UnitY, Vector3d.UnitZ);
            var barTop = new Vector3d(0, 0, SoccerGoal.HeightMetres + SoccerGoal.PostWidthMetres);
            double apex = CentreApexAfterBounce(model, frame, barTop, drop, 2);
            double eTopLow = RestitutionFor(model, drop, min - r), eTopHigh = RestitutionFor(model, drop, max - r);
            double eBottomLow = RestitutionFor(model, drop, min + r), eBottomHigh = RestitutionFor(model, drop, max + r);
            TestContext.Out.WriteLine(
                $"soccer ball on the crossbar (e {SportShapes.Post.NormalRestitution}): rebounds to {apex + r:F3} m (top of the ball), {apex - r:F3} m (bottom); " +
                $"FIFA {min}-{max} m: e {eTopLow:F3}-{eTopHigh:F3} read to the top, {eBottomLow:F3}-{eBottomHigh:F3} to the bottom");
            Assert.That(apex + r, Is.InRange(min, max), "measured to the top of the ball");
            Assert.That(apex - r, Is.LessThan(min), "documented miss: measured to the bottom of the ball");
            Assert.That(SportShapes.Post.NormalRestitution, Is.InRange(eTopLow, eTopHigh).And.LessThan(eBottomLow));
        }

        [Test]
        public void TennisBall_OnTheNetPost_ReboundsWithinTheItfBand()
        {
            // ITF: dropped from 254 cm onto a smooth granite block, a Type 2 ball rebounds 135-147 cm. Flown onto the flat top of
            // SportShapes.TennisNet's right post. In the band whichever point of the ball the heights are read to: the post's
            // 0.765 is inside both readings' restitutions (0.756-0.790 to the bottom, 0.737-0.771 to the top).
            JsonElement c = Case("tennis");
            double drop = c.Number("drop_height_m"), min = c.Number("rebound_min_m"), max = c.Number("rebound_max_m");
            FlightModel model = Model(SportPresets.Tennis);
            double r = model.Ball.Radius;
            ContactShape[] net = SportShapes.TennisNet(0, Vector3d.Zero, Vector3d.UnitY, Vector3d.UnitZ);
            double half = TennisCourt.DoublesWidthMetres / 2 + TennisCourt.PostsOutsideDoublesMetres;
            // 6 cm off the post's axis, across the net: on the post's 7.5 cm top, clear of the cord's end at the axis.
            var postTop = new Vector3d(0.06, half, TennisCourt.NetHeightAtPostsMetres);
            double apex = CentreApexAfterBounce(model, net, postTop, drop, 4);
            double eTopLow = RestitutionFor(model, drop, min - r), eTopHigh = RestitutionFor(model, drop, max - r);
            double eBottomLow = RestitutionFor(model, drop, min + r), eBottomHigh = RestitutionFor(model, drop, max + r);
            TestContext.Out.WriteLine(
                $"tennis ball on the net post (e {SportShapes.Post.NormalRestitution}): rebounds to {apex - r:F3} m (bottom of the ball), {apex + r:F3} m (top); " +
                $"ITF {min}-{max} m: e {eBottomLow:F3}-{eBottomHigh:F3} read to the bottom, {eTopLow:F3}-{eTopHigh:F3} to the top");
            Assert.That(apex - r, Is.InRange(min, max), "measured to the bottom of the ball");
            Assert.That(apex + r, Is.InRange(min, max), "measured to the top of the ball");
            Assert.That(SportShapes.Post.NormalRestitution, Is.InRange(Math.Max(eBottomLow, eTopLow), Math.Min(eBottomHigh, eTopHigh)));
        }
    }
}
