// A user's script in Assets/, written as the package's manual says: both namespaces imported, and `Plane` given a
// meaning by an alias. Without the alias, `Plane` below would be CS0104 (ambiguous between MagnusBall.Plane and
// UnityEngine.Plane).
using MagnusBall;
using MagnusBall.Components;
using MagnusBall.Flight;
using UnityEngine;
using Plane = MagnusBall.Plane;
using UnityPlane = UnityEngine.Plane;

/// <summary>Watches a net with the library's plane and tells which side of Unity's plane the ball lands on.</summary>
public class NetJudge : MonoBehaviour
{
    /// <summary>The ball.</summary>
    public MagnusBallFlight ball;

    private UnityPlane _centreLine;

    private void Start()
    {
        var net = new Plane(new Vector3d(0, 0, 0), new Vector3d(1, 0, 0)); // the library's: crossed along +x
        _centreLine = new UnityPlane(new Vector3(0f, 0f, 1f), new Vector3(0f, 0f, 0f)); // Unity's
        ball.Configure(ball.Model, ball.Integrator, ball.FixedStep, new FlightEventSet(UnityFrame.Up, ball.EventSet.Ground, new[] { net }), ball.BounceModel);
        ball.onLanded.AddListener(OnLanded);
    }

    private void OnLanded(FlightEvent landing)
    {
        MagnusBall.Plane fullyQualified = Plane.Ground(ball.Model); // the full name works as well
        float side = _centreLine.GetDistanceToPoint(UnityFrame.ToUnity(landing.Position));
        Debug.Log($"landed {(side > 0 ? "left" : "right")} of the centre line, {fullyQualified.SignedDistance(landing.Position):F3} m off the ground plane");
    }
}
