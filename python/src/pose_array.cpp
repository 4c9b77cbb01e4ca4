// Poses from NumPy: the checks of read_pose_file (finite numbers, translations within 1e16, a non-zero
// quaternion, normalised as there by Pose::from), plus rigidity for 4 x 4 transforms.
#include "pose_array.hpp"
#include "spt/pose_file.hpp"
#include <cmath>
#include <charconv>
#include <string>

namespace py = pybind11;

namespace spt::python {
namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// How far a 4 x 4 transform's rotation may be from orthonormal: float32 matrices and products of
// several rotations in double stay well within it; a scale of 1.00001 does not.
constexpr double kRigidTolerance = 1e-6;

// NumPy's own spelling of a shape, "(3, 5)" or "(7,)", so the message shows what the caller sees.
std::string shape_of(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

// The array as C-contiguous doubles. Integers and float32 convert exactly; bool, complex, text and
// objects are not numbers a pose is made of (TypeError).
Doubles as_doubles(const py::handle& obj, const char* name) {
    py::array a = py::array::ensure(obj);
    if (!a) throw py::type_error(std::string(name) + ": expected a NumPy array of numbers");
    const char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::type_error(std::string(name) + ": expected numbers (float64, float32 or integers), got dtype " +
                             py::str(a.dtype()).cast<std::string>());
    return Doubles::ensure(a);
}

// "poses row 2: why": the argument and the row as NumPy indexes it (the CLI's `pose` column).
[[noreturn]] void fail(const char* name, size_t row, const std::string& why) {
    throw py::value_error(std::string(name) + " row " + std::to_string(row) + ": " + why);
}

// The shortest text that reads back as x, as the user would have written it.
std::string number(double x) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, x).ptr;
    return std::string(text, end);
}

// What element k of a row is called in messages: a column of the pose file's, or a matrix entry.
std::string label(size_t n, size_t k) {
    static const char* const pose[] = {"tx", "ty", "tz", "qw", "qx", "qy", "qz"};
    static const char* const direction[] = {"dx", "dy", "dz"};
    if (n == 7) return pose[k];
    if (n == 3) return direction[k];
    return "[" + std::to_string(k / 4) + ", " + std::to_string(k % 4) + "]";
}

// A pose file's numbers must be finite.
void check_finite(const char* name, size_t row, const double* v, size_t n) {
    for (size_t k = 0; k < n; ++k)
        if (!std::isfinite(v[k])) fail(name, row, label(n, k) + " is " + number(v[k]) + ", not finite");
}

// The finite check, then a pose file's translation bound.
void check_row(const char* name, size_t row, const double* v, size_t n, const double* translation) {
    check_finite(name, row, v, n);
    for (int k = 0; k < 3; ++k)
        if (std::abs(translation[k]) > kMaxCoordinate)
            fail(name, row, "translation " + std::string(1, "xyz"[k]) + " = " + number(translation[k]) +
                                " is beyond 1e16 in magnitude (docs/queries.md, \"Extreme values\")");
}

// tx ty tz qw qx qy qz, checked and normalised as read_pose_file does a line.
Pose pose_from_row7(const char* name, size_t row, const double* v) {
    check_row(name, row, v, 7, v);
    const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
    if (q.coeffs().cwiseAbs().maxCoeff() == 0) fail(name, row, "the quaternion (qw qx qy qz) is zero");
    return Pose::from(Eigen::Vector3d(v[0], v[1], v[2]), q);
}

// A row-major 4 x 4 transform; refused unless rigid, since a pose cannot scale the model.
Pose pose_from_matrix(const char* name, size_t row, const double* v) {
    const double translation[3] = {v[3], v[7], v[11]};
    check_row(name, row, v, 16, translation);
    const Eigen::Matrix<double, 4, 4, Eigen::RowMajor> t(v);
    if (t(3, 0) != 0 || t(3, 1) != 0 || t(3, 2) != 0 || t(3, 3) != 1)
        fail(name, row, "not a rigid transform: the last row is not 0 0 0 1");
    const Eigen::Matrix3d r = t.topLeftCorner<3, 3>();
    const double off = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(off <= kRigidTolerance) || r.determinant() < 0)
        fail(name, row, "not a rigid transform: the 3 x 3 part is not a rotation (scaled, sheared or mirrored)");
    return Pose::from(Eigen::Vector3d(translation[0], translation[1], translation[2]), Eigen::Quaterniond(r));
}

} // namespace

std::vector<Pose> poses_from_array(const py::handle& array, const char* name) {
    const Doubles a = as_doubles(array, name);
    const bool rows7 = a.ndim() == 2 && a.shape(1) == 7;
    const bool matrices = a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 4;
    if (!rows7 && !matrices)
        throw py::value_error(std::string(name) + ": expected an N x 7 array (tx ty tz qw qx qy qz) or N x 4 x 4 "
                              "rigid transforms, got shape " + shape_of(a));
    const size_t n = size_t(a.shape(0));
    const double* data = a.data();
    std::vector<Pose> poses(n);
    for (size_t i = 0; i < n; ++i)
        poses[i] = rows7 ? pose_from_row7(name, i, data + 7 * i) : pose_from_matrix(name, i, data + 16 * i);
    return poses;
}

std::vector<Eigen::Vector3d> directions_from_array(const py::handle& array, const char* name, size_t rows) {
    const Doubles a = as_doubles(array, name);
    if (a.ndim() != 2 || a.shape(1) != 3 || size_t(a.shape(0)) != rows)
        throw py::value_error(std::string(name) + ": expected an N x 3 array (dx dy dz) with a row for each of the " +
                              std::to_string(rows) + " poses, got shape " + shape_of(a));
    std::vector<Eigen::Vector3d> out(rows);
    for (size_t i = 0; i < rows; ++i) {
        const double* v = a.data() + 3 * i;
        check_finite(name, i, v, 3);
        out[i] = Eigen::Vector3d(v[0], v[1], v[2]);
    }
    return out;
}

} // namespace spt::python
