using System;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.Integration;
using NUnit.Framework;

namespace MagnusBall.Tests.Contact
{
    /// <summary>A degenerate shape is refused with an ArgumentException naming the parameter and its range (issue 40).</summary>
    public class ContactShapeBadInputTests
    {
        private static readonly ContactProperties C = new ContactProperties(0.5, 0.3);
        private static readonly Vector3d A = new Vector3d(0, 0, 0), B = new Vector3d(0, 0, 1);

        private static void Refused(TestDelegate make, string parameter, string range)
        {
            var e = Assert.Throws(Is.InstanceOf<ArgumentException>(), make) as ArgumentException;
            Assert.That(e!.ParamName, Is.EqualTo(parameter));
            Assert.That(e.Message, Does.Contain(range));
        }

        [TestCase(0.0)]
        [TestCase(-0.01)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        public void Radius_NotFiniteAndPositive_IsRefused(double radius)
        {
            Refused(() => new CapsuleShape(1, A, B, radius, C), "radiusM", "> 0");
            Refused(() => new CylinderShape(1, A, B, radius, C), "radiusM", "> 0");
            Refused(() => new TorusShape(1, A, B, radius, 0.01, C), "ringRadiusM", "> 0");
            Refused(() => new TorusShape(1, A, B, 0.2, radius, C), "tubeRadiusM", "> 0");
        }

        [Test]
        public void ZeroLengthAxis_OrZeroNormal_IsRefused()
        {
            Refused(() => new CapsuleShape(1, A, A, 0.1, C), "endB", "between 1e-150 m");
            Refused(() => new CapsuleShape(1, A, A + new Vector3d(1e-170, 0, 0), 0.1, C), "endB", "between 1e-150 m"); // its square would underflow
            Refused(() => new CylinderShape(1, B, B, 0.1, C), "endB", "between 1e-150 m");
            Refused(() => new TorusShape(1, A, Vector3d.Zero, 0.2, 0.01, C), "axis", "non-zero");
            Refused(() => BoxShape.Rectangle(1, A, Vector3d.Zero, Vector3d.UnitX, 1, 1, C), "normal", "non-zero");
            Refused(() => BoxShape.Rectangle(1, A, Vector3d.UnitX, Vector3d.UnitX * 2, 1, 1, C), "widthDirection", "not be along");
            Refused(() => new NetMeshShape(1, A, Vector3d.Zero, Vector3d.UnitY, 1, 1), "normal", "non-zero");
            Refused(() => new SphereShape(1, A, 0, C), "radiusM", "> 0");
            Refused(() => new SphereShape(1, new Vector3d(double.NaN, 0, 0), 0.1, C), "centre", "finite");
        }

        [Test]
        public void NegativeOrNonFiniteExtent_IsRefused()
        {
            Refused(() => new BoxShape(1, A, new Vector3d(1, -0.1, 1), Vector3d.UnitX, Vector3d.UnitY, C), "halfExtentsM", ">= 0");
            Refused(() => new BoxShape(1, A, new Vector3d(1, double.NaN, 1), Vector3d.UnitX, Vector3d.UnitY, C), "halfExtentsM", "finite");
            Refused(() => BoxShape.Rectangle(1, A, Vector3d.UnitZ, Vector3d.UnitX, -1, 1, C), "widthM", "> 0");
            Refused(() => BoxShape.Rectangle(1, A, Vector3d.UnitZ, Vector3d.UnitX, 0, 1, C), "widthM", "> 0"); // a segment, not a rectangle
            Refused(() => new BoxShape(1, A, new Vector3d(0, 0, 1), Vector3d.UnitX, Vector3d.UnitY, C), "halfExtentsM", "at most one of them 0");
            Refused(() => new BoxShape(1, A, new Vector3d(1, 1, 1), Vector3d.UnitX, Vector3d.UnitX, C), "yAxis", "not be parallel");
        }

        [Test]
        public void NonFinitePoint_BadMass_OrKeptFraction_IsRefused()
        {
            Refused(() => new CapsuleShape(1, new Vector3d(double.NaN, 0, 0), B, 0.1, C), "endA", "finite");
            Refused(() => new TorusShape(1, new Vector3d(0, double.PositiveInfinity, 0), B, 0.2, 0.01, C), "centre", "finite");
            Refused(() => new CapsuleShape(1, A, B, 0.1, C, 0), "effectiveMassKg", "> 0");
            Refused(() => new CapsuleShape(1, A, B, 0.1, C, double.NaN), "effectiveMassKg", "> 0");
            // A body lighter than 1e-12 of the ball is refused by the flight that would fly it, before any step (the impact
            // law's limit), not in the middle of one.
            FlightModel model = MagnusBall.Presets.SportPresets.Tennis.CreateModel(Air.SeaLevel, Gravity.ZUp);
            var feather = new CapsuleShape(1, A, B, 0.1, C, 1e-20);
            var e = Assert.Throws<ArgumentException>(() => new MagnusBall.Flight.FlightStepper(model, MagnusBall.Integration.RungeKutta4.Instance, shapes: new ContactShape[] { feather }));
            Assert.That(e!.ParamName, Is.EqualTo("shapes"));
            Assert.That(e.Message, Does.Contain("at least 1e-12 of the ball's mass"));
            Refused(() => new NetMeshShape(1, A, Vector3d.UnitX, Vector3d.UnitY, 1, 1, 1.5), "tangentialSpeedKept", "[0, 1]");
            Refused(() => new NetMeshShape(1, A, Vector3d.UnitX, Vector3d.UnitY, 1, 1, 0.25, -0.2), "effectiveMassKg", "> 0");
        }

        [Test]
        public void NullShape_IsRefused_ByTheStepper()
        {
            var model = new FlightModel(Ball.Tennis, Air.Vacuum, Gravity.ZUp);
            Refused(() => new FlightStepper(model, RungeKutta4.Instance, null, null, new ContactShape[] { null! }), "shapes", "null");
        }
    }
}
