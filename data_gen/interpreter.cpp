#include "data_gen/interpreter.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/memory_budget.h"
#include "base/random.h"
#include "data_gen/expression.h"
#include "data_gen/primitives.h"
#include "data_gen/split.h"
#include "toolkit/formats/model_io.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>

namespace boxlod {

namespace {

// What flows through a rule's operations: the current scope and look.
struct Shape {
    ScopeBox scope;
    Appearance appearance;
};

// One rule application, i.e. one node of the derivation tree.
struct Application {
    int node;
    const Rule* rule;
    std::vector<double> arguments;
    ScopeBox entry;  // the scope the symbol was given (stored in the node)
    std::uint64_t identity;
    Pcg32 random;
    int depth;
    std::uint64_t children = 0;
};

int axis_index(char axis) { return axis - 'x'; }

using Attributes = std::vector<std::pair<std::string, double>>;

// The latest definition of an attribute wins.
bool find_attribute(const Attributes& attributes, const std::string& name, double& value) {
    for (auto it = attributes.rbegin(); it != attributes.rend(); ++it)
        if (it->first == name) return value = it->second, true;
    return false;
}

class Interpreter {
public:
    Interpreter(const Grammar& grammar, std::uint64_t seed, Model& model, MaterialCache& materials,
                const DerivationLimits& limits)
        : grammar_(grammar), seed_(seed), model_(model), materials_(materials), limits_(limits) {
        attributes_ = evaluate_attributes(grammar, seed);
    }

    static Attributes evaluate_attributes(const Grammar& grammar, std::uint64_t seed) {
        Attributes values;
        Pcg32 random(seed, 0);  // stream 0: the attributes; nodes use hashed identities
        VariableLookup lookup = [&](const std::string& name, double& value) {
            return find_attribute(values, name, value);
        };
        for (const Attribute& attribute : grammar.attributes)
            values.emplace_back(attribute.name, evaluate(attribute.value, lookup, random, grammar.file));
        return values;
    }

    int apply(const Rule& rule, std::vector<double> arguments, const Shape& shape, int parent,
              std::uint64_t identity, int depth, SourcePlace called_from) {
        if (depth > limits_.max_depth)
            throw_grammar_error(grammar_.file, called_from,
                                "rule '" + rule.symbol + "' nested deeper than " +
                                    std::to_string(limits_.max_depth) +
                                    " levels (recursion that never ends?)");
        if (++nodes_made_ > limits_.max_nodes)
            throw_grammar_error(grammar_.file, called_from,
                                "the derivation makes more than " + std::to_string(limits_.max_nodes) +
                                    " nodes (recursion that never ends?)");
        int node = add_node(model_, parent, rule.symbol);
        charge(2 * double(sizeof(Node)) +
               2 * double(rule.symbol.capacity()));  // the node vector grows by doubling
        model_.nodes[node].rule = rule.symbol;
        model_.nodes[node].scope = to_scope(shape.scope);
        Application application{
            node, &rule, std::move(arguments), shape.scope, identity, Pcg32(seed_, identity), depth};
        Shape current = shape;
        if (const Alternative* chosen = choose(application, current)) run(chosen->body, current, application);
        return node;
    }

private:
    const Grammar& grammar_;
    std::uint64_t seed_;
    Model& model_;
    MaterialCache& materials_;
    DerivationLimits limits_;
    Attributes attributes_;
    std::map<std::string, std::vector<Primitive>> assets_;
    std::size_t nodes_made_ = 0, shapes_made_ = 0;
    double model_memory_ = 0;

    // The derivation's model is checked against the memory budget as it grows (docs/design.md: Errors): a
    // few lines of grammar can ask for billions of triangles within the node limit.
    void charge(double bytes) {
        model_memory_ += bytes;
        check_memory(grammar_.file + ": the derivation's model", model_memory_);
    }

    // Counts split pieces, as laid out (each held until its split ends), or a component against max_shapes.
    void made_shapes(const Operation& op, std::size_t count) {
        if ((shapes_made_ += count) > limits_.max_shapes)
            fail(op.place, "the derivation makes more than " + std::to_string(limits_.max_shapes) +
                               " split pieces and components (splits nested too finely?)");
    }

    [[noreturn]] void fail(SourcePlace place, const std::string& what) const {
        throw_grammar_error(grammar_.file, place, what);
    }

    double value(const Expression& expression, const Shape& shape, Application& application) {
        VariableLookup lookup = [&](const std::string& name, double& out) {
            const Rule& rule = *application.rule;
            for (std::size_t i = 0; i < rule.parameters.size(); ++i)
                if (rule.parameters[i] == name) return out = application.arguments[i], true;
            if (name == "scope.sx") return out = shape.scope.size.x(), true;
            if (name == "scope.sy") return out = shape.scope.size.y(), true;
            if (name == "scope.sz") return out = shape.scope.size.z(), true;
            return find_attribute(attributes_, name, out);
        };
        return evaluate(expression, lookup, application.random, grammar_.file);
    }

    const Alternative* choose(Application& application, const Shape& shape) {
        const std::vector<Alternative>& alternatives = application.rule->alternatives;
        if (alternatives[0].kind == Alternative::Kind::always) return &alternatives[0];
        double draw =
            alternatives[0].kind == Alternative::Kind::probability ? application.random.uniform() * 100 : 0;
        double cumulative = 0;
        for (const Alternative& alternative : alternatives) {
            if (alternative.kind == Alternative::Kind::otherwise) return &alternative;
            if (alternative.kind == Alternative::Kind::probability) {
                cumulative += alternative.percent;
                if (draw < cumulative) return &alternative;
            } else if (value(alternative.condition, shape, application) != 0) {
                return &alternative;
            }
        }
        return nullptr;  // no alternative applies: the shape stays as it is
    }

    // Returns false when NIL ended the sequence.
    bool run(const Sequence& sequence, Shape& shape, Application& application) {
        for (const Operation& op : sequence) {
            switch (op.kind) {
            case Operation::Kind::nil: return false;
            case Operation::Kind::symbol: call(op, shape, application); break;
            case Operation::Kind::extrude: extrude(op, shape, application); break;
            case Operation::Kind::split: split(op, shape, application); break;
            case Operation::Kind::component: component(op, shape, application); break;
            case Operation::Kind::translate:
                for (int a = 0; a < 3; ++a)
                    shape.scope.origin += shape.scope.axes.col(a) * float(amount(op, a, shape, application));
                break;
            case Operation::Kind::rotate: rotate(op, shape, application); break;
            case Operation::Kind::scale: {
                Eigen::Vector3f size;
                for (int a = 0; a < 3; ++a) size[a] = float(amount(op, a, shape, application));
                if ((size.array() < 0).any()) fail(op.place, "s() cannot make a negative size");
                shape.scope.size = size;
                break;
            }
            case Operation::Kind::center: {
                Eigen::Vector3f offset = application.entry.center() - shape.scope.center();
                for (char axis : op.name) {
                    Eigen::Vector3f direction = shape.scope.axes.col(axis_index(axis));
                    shape.scope.origin += direction * direction.dot(offset);
                }
                break;
            }
            case Operation::Kind::insert: insert(op, shape, application); break;
            case Operation::Kind::material: shape.appearance = Appearance{op.name, std::nullopt, ""}; break;
            case Operation::Kind::texture: shape.appearance.texture = op.name; break;
            case Operation::Kind::color: shape.appearance.color = color(op, shape, application); break;
            case Operation::Kind::push: {
                Shape inner = shape;
                run(op.body, inner, application);
                break;
            }
            }
            if (!in_world(shape.scope))
                fail(op.place, "the scope leaves the world: a coordinate or size beyond " +
                                   std::to_string(long(max_world_extent)) + " m, or not a number");
        }
        return true;
    }

    static bool in_world(const ScopeBox& scope) {
        auto bounded = [](const auto& v) {
            return v.allFinite() && v.cwiseAbs().maxCoeff() <= max_world_extent;
        };
        return bounded(scope.origin) && bounded(scope.size) && scope.axes.allFinite();
    }

    // Argument `a` of t() or s(): metres, or 'relative to the scope's size.
    double amount(const Operation& op, int a, const Shape& shape, Application& application) {
        double v = value(op.arguments[a].value, shape, application);
        return op.arguments[a].kind == Size::Kind::relative ? v * shape.scope.size[a] : v;
    }

    void call(const Operation& op, const Shape& shape, Application& application) {
        const Rule* rule = grammar_.find(op.name);
        std::vector<double> arguments;
        for (const Size& argument : op.arguments)
            arguments.push_back(value(argument.value, shape, application));
        std::uint64_t identity = hash_combine(application.identity, application.children++);
        apply(*rule, std::move(arguments), shape, application.node, identity, application.depth + 1,
              op.place);
    }

    void extrude(const Operation& op, Shape& shape, Application& application) {
        double height = value(op.arguments[0].value, shape, application);
        if (height < 0) fail(op.place, "extrude() needs a height of at least 0");
        int axis = -1;
        if (!op.name.empty()) {
            axis = axis_index(op.name[0]);
        } else {
            for (int candidate : {1, 2, 0})  // a lot is flat in y, a facade in z
                if (axis < 0 && shape.scope.size[candidate] <= 1e-6f) axis = candidate;
            if (axis < 0)
                fail(op.place,
                     "extrude() needs a flat scope; name the axis for a solid one, e.g. extrude(y, 3)");
        }
        shape.scope.size[axis] = float(height);
    }

    void split(const Operation& op, const Shape& shape, Application& application) {
        int axis = axis_index(op.name[0]);
        std::vector<SplitSlot> slots;
        std::vector<const SplitEntry*> entries;
        auto add = [&](const SplitEntry& item, bool repeated) {
            double size = value(item.size.value, shape, application);
            if (size < 0) fail(item.place, "a split size cannot be negative");
            slots.push_back({item.size.kind, size, repeated});
            entries.push_back(&item);
        };
        for (const SplitEntry& entry : op.entries) {
            if (entry.repeated.empty()) add(entry, false);
            for (const SplitEntry& item : entry.repeated) add(item, true);
        }
        double extent = shape.scope.size[axis];
        // Room for one piece past the limit after a whole repetition, so that a split the limit cuts short
        // is refused by made_shapes, never laid out short.
        SplitLayout layout =
            layout_split(slots, extent, limits_.max_shapes - shapes_made_ + 1 + slots.size());
        if (!layout.fits) {
            char text[160];
            std::snprintf(
                text, sizeof text, "split(%s) in rule '%s' needs %.4g m but the scope is %.4g m along %s",
                op.name.c_str(), application.rule->symbol.c_str(), layout.needed, extent, op.name.c_str());
            fail(op.place, text);
        }
        made_shapes(op, layout.pieces.size());
        for (const SplitPiece& piece : layout.pieces) {
            Shape part = shape;
            part.scope.origin += shape.scope.axes.col(axis) * float(piece.offset);
            part.scope.size[axis] = float(piece.size);
            run(entries[piece.slot]->successor, part, application);
        }
    }

    void component(const Operation& op, const Shape& shape, Application& application) {
        for (const ScopeFace& face : scope_faces(shape.scope.size)) {
            if (face.width <= 1e-6f || face.height <= 1e-6f) continue;
            const SplitEntry* taken = nullptr;
            for (const SplitEntry& entry : op.entries)
                if (!taken && entry.selector && selects(*entry.selector, face.name)) taken = &entry;
            if (!taken) continue;
            made_shapes(op, 1);
            Shape part = shape;
            part.scope.origin = shape.scope.to_world(face.origin);
            part.scope.axes.col(0) = shape.scope.axes * face.u;
            part.scope.axes.col(1) = shape.scope.axes * face.v;
            part.scope.axes.col(2) = shape.scope.axes * face.u.cross(face.v);
            part.scope.size = Eigen::Vector3f(face.width, face.height, 0);
            run(taken->successor, part, application);
        }
    }

    void rotate(const Operation& op, Shape& shape, Application& application) {
        Eigen::Matrix3f turn = Eigen::Matrix3f::Identity();
        for (int a = 0; a < 3; ++a) {
            double radians = value(op.arguments[a].value, shape, application) * std::numbers::pi / 180;
            turn = turn * Eigen::AngleAxisf(float(radians), Eigen::Vector3f::Unit(a)).toRotationMatrix();
        }
        Eigen::Vector3f center = shape.scope.center();  // turn about the centre, not the corner
        shape.scope.axes = shape.scope.axes * turn;
        shape.scope.origin = center - shape.scope.axes * (shape.scope.size / 2);
    }

    Eigen::Vector3f color(const Operation& op, const Shape& shape, Application& application) {
        if (op.name_is_text) {
            auto hex = [&](int at) { return float(std::stoi(op.name.substr(at, 2), nullptr, 16)) / 255.0f; };
            return {hex(1), hex(3), hex(5)};
        }
        Eigen::Vector3f c;
        for (int k = 0; k < 3; ++k) {
            const double v = value(op.arguments[k].value, shape, application);
            if (!(v >= 0 && v <= 1))
                fail(op.place, "color: " + format_number(v) + " is not an sRGB value in [0, 1]");
            c[k] = float(v);
        }
        return c;
    }

    void insert(const Operation& op, const Shape& shape, Application& application) {
        std::vector<Primitive> primitives;
        if (op.name_is_text) {
            primitives = fitted_asset(op, shape.scope.size);
        } else {
            int segments = op.arguments.empty()
                               ? 12
                               : int(std::lround(value(op.arguments[0].value, shape, application)));
            if (segments < 3 || segments > 256) fail(op.place, "a cylinder needs 3 to 256 segments");
            primitives.push_back(builtin_primitive(op.name, shape.scope.size, segments));
        }
        for (Primitive& primitive : primitives) {
            if (primitive.indices.empty()) continue;
            place_in_world(primitive, shape.scope);
            if (!op.name_is_text)
                planar_texture_coordinates(primitive, materials_.tile_metres(shape.appearance));
            primitive.material = materials_.index(model_, shape.appearance);
            charge(double(sizeof(Primitive)) + 48 * double(primitive.positions.size()) +
                   4 * double(primitive.indices.size()));  // positions, normals, uvs, tangents
            model_.nodes[application.node].primitives.push_back(std::move(primitive));
        }
    }

    // An asset's primitives scaled so its bounding box fills the scope (an
    // axis where the scope is flat keeps the asset's own size), in the scope's metres.
    std::vector<Primitive> fitted_asset(const Operation& op, const Eigen::Vector3f& size) {
        auto found = assets_.find(op.name);
        if (found == assets_.end()) {
            std::filesystem::path path = std::filesystem::path(grammar_.directory) / op.name;
            Model asset;
            try {
                asset = load_model(path.string());
            } catch (const InputError& error) {
                fail(op.place, "cannot load asset '" + op.name + "': " + error.what());
            }
            std::vector<Primitive> primitives;
            for (Node& node : asset.nodes)
                for (Primitive& primitive : node.primitives) primitives.push_back(std::move(primitive));
            found = assets_.emplace(op.name, std::move(primitives)).first;
        }
        Bounds bounds;
        for (const Primitive& primitive : found->second)
            for (const Eigen::Vector3f& p : primitive.positions) bounds.add(p);
        Eigen::Vector3f extent = bounds.size(), stretch;
        for (int a = 0; a < 3; ++a)
            stretch[a] = extent[a] > 1e-9f && size[a] > 1e-6f ? size[a] / extent[a] : 1.0f;
        std::vector<Primitive> fitted = found->second;
        for (Primitive& primitive : fitted) {
            for (Eigen::Vector3f& p : primitive.positions) p = (p - bounds.min).cwiseProduct(stretch);
            // Normals take the inverse scale, tangents the scale itself.
            for (Eigen::Vector3f& n : primitive.normals) n = n.cwiseQuotient(stretch).normalized();
            for (Eigen::Vector4f& t : primitive.tangents)
                t.head<3>() = t.head<3>().cwiseProduct(stretch).normalized();
        }
        return fitted;
    }
};

}  // namespace

int derive(const Grammar& grammar, const std::string& start, const ScopeBox& lot, std::uint64_t seed,
           Model& model, int parent, MaterialCache& materials, const DerivationLimits& limits) {
    const Rule* rule = start.empty() ? &grammar.rules[0] : grammar.find(start);
    if (!rule) throw_input_error(grammar.file, "", "unknown start symbol '" + start + "'");
    if (!rule->parameters.empty())
        throw_grammar_error(grammar.file, rule->place,
                            "the start rule '" + rule->symbol + "' cannot take parameters");
    Interpreter interpreter(grammar, seed, model, materials, limits);
    Shape shape{lot, Appearance{}};
    return interpreter.apply(*rule, {}, shape, parent, 1, 0, rule->place);
}

Eigen::Vector2f default_lot(const Grammar& grammar, std::uint64_t seed) {
    Eigen::Vector2f lot(20, 20);
    for (const auto& [name, value] : Interpreter::evaluate_attributes(grammar, seed)) {
        if (name == "lot_width") lot.x() = float(value);
        if (name == "lot_depth") lot.y() = float(value);
    }
    return lot;
}

ScopeBox ground_lot(float width, float depth, const Eigen::Vector3f& center) {
    ScopeBox lot;
    lot.origin = center - Eigen::Vector3f(width / 2, 0, depth / 2);
    lot.size = Eigen::Vector3f(width, 0, depth);
    return lot;
}

Model generate_building(const Grammar& grammar, const BuildingOptions& options) {
    Eigen::Vector2f lot = options.lot.value_or(default_lot(grammar, options.seed));
    if (!(lot.array() > 0).all() || !(lot.array() <= max_world_extent).all())
        throw_input_error(
            grammar.file, "",
            "the lot's width and depth must be in (0, " + std::to_string(long(max_world_extent)) + "] m");
    Model model;
    model.source = grammar.file;
    MaterialCache materials;
    derive(grammar, options.start, ground_lot(lot.x(), lot.y()), options.seed, model, -1, materials,
           options.limits);
    return model;
}

}  // namespace boxlod
