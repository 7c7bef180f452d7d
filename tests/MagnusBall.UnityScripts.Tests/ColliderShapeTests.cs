using System;
using System.Collections.Generic;
using MagnusBall.Components;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Flight;
using MagnusBall.UnityStubs;
using NUnit.Framework;
using UnityEngine;
using static MagnusBall.UnityScripts.Tests.UnityLoop;

namespace MagnusBall.UnityScripts.Tests
{
    /// <summary>
    /// Issue 40, item 6c: the flight component takes shapes, built from the scene's colliders where the match is exact
    /// (ColliderShapes: a BoxCollider a box, a CapsuleCollider a capsule; a SphereCollider and anything inexact skipped with a
    /// warning), and raises a Contacted event when the ball hits one.
    /// </summary>
    [TestFixture]
    [NonParallelizable] // the stub's Time and log are static, as Unity's are
    public class ColliderShapeTests
    {
        private static readonly ContactProperties Wall = new ContactProperties(0.7, 0.3);

        private static T Collider<T>(string name, Vector3 position, Quaternion rotation, Vector3 scale)
            where T : Component
        {
            var holder = new GameObject(name);
            holder.transform.position = position;
            holder.transform.rotation = rotation;
            holder.transform.localScale = scale;
            return holder.AddComponent<T>();
        }

        [Test]
        public void ABoxCollider_RotatedAndScaled_IsTheSameBox()
        {
            BoxCollider box = Collider<BoxCollider>("wall", new Vector3(5, 1, 0), Quaternion.AngleAxis(30, new Vector3(0, 1, 0)), new Vector3(0.2f, 2, 4));
            box.center = new Vector3(0, 0.25f, 0);
            ContactShape[] shapes = ColliderShapes.FromColliders(new Collider[] { box }, Wall, firstId: 7);
            Assert.That(shapes, Has.Length.EqualTo(1));
            var shape = (BoxShape)shapes[0];
            Assert.That(shape.Id, Is.EqualTo(7));
            Assert.That(shape.Centre.Y, Is.EqualTo(1 + 0.25 * 2).Within(1e-6), "the centre through the transform (scaled)");
            Assert.That(shape.HalfExtentsM.X, Is.EqualTo(0.1).Within(1e-6));
            Assert.That(shape.HalfExtentsM.Y, Is.EqualTo(1).Within(1e-6));
            Assert.That(shape.HalfExtentsM.Z, Is.EqualTo(2).Within(1e-6));
            // The box's z axis: the transform's forward, turned 30 degrees about up.
            Assert.That(shape.ZAxis.X, Is.EqualTo(Math.Sin(Math.PI / 6)).Within(1e-6));
            Assert.That(shape.ZAxis.Z, Is.EqualTo(Math.Cos(Math.PI / 6)).Within(1e-6));
            Assert.That(shape.Contact.NormalRestitution, Is.EqualTo(0.7));
        }

        [Test]
        public void ACapsuleCollider_IsTheSameCapsule_AlongItsDirection()
        {
            CapsuleCollider post = Collider<CapsuleCollider>("post", new Vector3(3, 0, 0), Quaternion.identity, new Vector3(2, 2, 2));
            post.direction = 2; // along z
            post.height = 2;    // end to end, caps included: 4 m scaled
            post.radius = 0.05f; // 0.1 m scaled
            var shape = (CapsuleShape)ColliderShapes.FromColliders(new Collider[] { post }, Wall)[0];
            Assert.That(shape.RadiusM, Is.EqualTo(0.1).Within(1e-6));
            Assert.That(shape.EndA.Z, Is.EqualTo(-1.9).Within(1e-6));
            Assert.That(shape.EndB.Z, Is.EqualTo(1.9).Within(1e-6));
            Assert.That(shape.EndA.X, Is.EqualTo(3).Within(1e-6));
        }

        [Test]
        public void SpheresAndShortCapsules_AreSpheres_AnEggAnEllipticalCapsuleAndAnEmptySlot_AreSkippedWithAWarning()
        {
            StubControl.Logged.Clear();
            SphereCollider ball = Collider<SphereCollider>("boulder", new Vector3(1, 0, 0), Quaternion.identity, new Vector3(2, 2, 2));
            ball.radius = 0.25f;
            CapsuleCollider stub = Collider<CapsuleCollider>("stub", new Vector3(2, 0, 0), Quaternion.identity, new Vector3(1, 1, 1));
            stub.height = 0.5f; // below twice the radius (1): a sphere
            SphereCollider egg = Collider<SphereCollider>("egg", new Vector3(5, 0, 0), Quaternion.identity, new Vector3(1, 2, 1));
            CapsuleCollider squashed = Collider<CapsuleCollider>("squashed", new Vector3(3, 0, 0), Quaternion.identity, new Vector3(1, 1, 3));
            BoxCollider box = Collider<BoxCollider>("box", new Vector3(4, 0, 0), Quaternion.identity, new Vector3(1, 1, 1));
            var skipped = new List<string>();
            ContactShape[] shapes = ColliderShapes.FromColliders(new Collider?[] { ball, stub, squashed, null, box, egg }, Wall, 0, skipped);
            Assert.That(shapes, Has.Length.EqualTo(3), "the sphere, the capsule that is a sphere, the box");
            var sphere = (SphereShape)shapes[0];
            Assert.That(sphere.Id, Is.EqualTo(0));
            Assert.That(sphere.RadiusM, Is.EqualTo(0.5).Within(1e-6), "0.25 scaled by 2");
            Assert.That(((SphereShape)shapes[1]).RadiusM, Is.EqualTo(0.5).Within(1e-6), "the capsule's radius");
            Assert.That(shapes[2].Id, Is.EqualTo(4), "its index: ids stay put when others are skipped");
            Assert.That(skipped, Has.Count.EqualTo(3));
            Assert.That(skipped[0], Does.Contain("'squashed'").And.Contain("differently across its axis"));
            Assert.That(skipped[1], Does.Contain("no collider assigned"));
            Assert.That(skipped[2], Does.Contain("'egg'").And.Contain("ellipsoid"));
            Assert.That(StubControl.Logged.FindAll(l => l.StartsWith("Warning: MagnusBall: collider", StringComparison.Ordinal)), Has.Count.EqualTo(3));
        }

        [Test]
        public void ABoxSkewedByItsParent_IsSkipped()
        {
            var parent = new GameObject("stretched");
            parent.transform.localScale = new Vector3(1, 3, 1);
            BoxCollider box = Collider<BoxCollider>("tilted", Vector3.zero, Quaternion.AngleAxis(45, new Vector3(0, 0, 1)), new Vector3(1, 1, 1));
            box.transform.SetParent(parent.transform, false);
            var skipped = new List<string>();
            Assert.That(ColliderShapes.FromColliders(new Collider[] { box }, Wall, 0, skipped), Is.Empty);
            Assert.That(skipped[0], Does.Contain("skews the box"));
        }

        [Test]
        public void TheFlightComponent_HitsAWallCollider_RaisesContacted_AndComesBack()
        {
            BoxCollider wall = Collider<BoxCollider>("wall", new Vector3(8, 2, 0), Quaternion.identity, new Vector3(0.2f, 4, 10));
            var holder = new GameObject("ball");
            holder.transform.position = new Vector3(0, 1.5f, 0);
            MagnusBallFlight flight = Add<MagnusBallFlight>(holder);
            flight.shapeColliders.Add(wall);
            flight.shapeRestitution = 0.6f;
            flight.ApplySettings();
            var contacts = new List<FlightEvent>();
            flight.Contacted += contacts.Add;
            int unity = 0;
            flight.onContact.AddListener(_ => unity++);
            flight.Launch(new Vector3(20, 3, 0), Vector3.zero);
            StubControl.DeltaTime = 1f / 60f;
            for (int frame = 0; frame < 2000 && flight.IsFlying; frame++)
            {
                Call(flight, "Update");
            }

            Assert.That(contacts, Has.Count.EqualTo(1));
            Assert.That(unity, Is.EqualTo(1));
            FlightEvent hit = contacts[0];
            Assert.That(hit.ShapeId, Is.EqualTo(0), "its index in shapeColliders");
            Assert.That(hit.Position.X, Is.EqualTo(8 - 0.1 - flight.Model.Ball.Radius).Within(1e-6), "the ball's surface on the wall's face (the collider's floats)");
            Assert.That(hit.ContactNormal.X, Is.EqualTo(-1).Within(1e-12));
            Assert.That(hit.After.Velocity.X, Is.LessThan(0), "it comes back");
            Assert.That(flight.ArcStart.Time, Is.GreaterThanOrEqualTo(hit.Time), "a new arc from the hit (the preview follows it)");

            flight.shapeRestitution = 1.5f;
            var refused = Assert.Throws<ArgumentOutOfRangeException>(() => flight.ApplySettings())!;
            Assert.That(refused.ParamName, Is.EqualTo("shapeRestitution"));
        }

        [Test]
        public void ThePreview_PredictsWithTheFlightsShapes_TheLineTurnsAtTheWall()
        {
            // The preview predicts with the ball's shapes: the line of a shot at the wall comes back off its face (before, it
            // went through the wall to the ground behind it).
            BoxCollider wall = Collider<BoxCollider>("wall", new Vector3(8, 2, 0), Quaternion.identity, new Vector3(0.2f, 4, 10));
            var holder = new GameObject("ball");
            holder.transform.position = new Vector3(0, 1.5f, 0);
            MagnusBallFlight flight = Add<MagnusBallFlight>(holder);
            flight.shapeColliders.Add(wall);
            flight.ApplySettings();
            var lineHolder = new GameObject("line");
            LineRenderer line = lineHolder.AddComponent<LineRenderer>();
            MagnusBallTrajectoryPreview preview = Add<MagnusBallTrajectoryPreview>(lineHolder);
            preview.flight = flight;
            preview.Show(new FlightState(new Vector3d(0, 1.5, 0), new Vector3d(20, 3, 0), Vector3d.Zero));
            Call(preview, "LateUpdate");
            Assert.That(line.positionCount, Is.GreaterThan(2));
            double face = 8 - 0.1 - flight.Model.Ball.Radius;
            float furthest = float.NegativeInfinity;
            for (int i = 0; i < line.positionCount; i++)
            {
                furthest = Math.Max(furthest, line.GetPosition(i).x);
            }

            Assert.That(furthest, Is.LessThanOrEqualTo(face + 1e-5), "no point beyond the wall's face");
            Assert.That(line.GetPosition(line.positionCount - 1).x, Is.LessThan(face - 1), "it ends back in front of the wall");
        }
    }
}
